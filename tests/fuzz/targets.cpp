#include "targets.h"

#include "basis_target.h"
#include "gltf_targets.h"
#include "texture_targets.h"

namespace sherpa::fuzz {

std::vector<std::unique_ptr<Target>> make_targets() {
    std::vector<std::unique_ptr<Target>> t;
    t.push_back(std::make_unique<GltfTarget>());
    t.push_back(std::make_unique<GlbTarget>());
    t.push_back(std::make_unique<TangentsTarget>());
    t.push_back(std::make_unique<Ktx2Target>());
    t.push_back(std::make_unique<CacheTarget>());
    t.push_back(std::make_unique<BasisTarget>());
    return t;
}

} // namespace sherpa::fuzz
