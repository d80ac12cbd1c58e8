#include "targets.h"

#include "basis_target.h"
#include "compressed_targets.h"
#include "gltf_targets.h"
#include "image_target.h"
#include "meshopt_codec_target.h"
#include "pose_target.h"
#include "texture_targets.h"
#include "validate_target.h"

#include <fstream>

namespace sherpa::fuzz {

namespace fs = std::filesystem;

void write_case_file(const fs::path& path, std::span<const std::uint8_t> bytes) {
    fs::remove(path);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

fs::path ByteTarget::make_case(Rng& rng) {
    bytes_ = seeds_[rng.below(seeds_.size())];
    mutate_bytes(rng, bytes_, seeds_[rng.below(seeds_.size())], config_.max_size);
    // The file is the reproducer; the code under test works on memory.
    write_case_file(config_.work_dir / case_name_, bytes_);
    return config_.work_dir;
}

std::vector<fs::path> ByteTarget::case_files() const {
    return {config_.work_dir / case_name_};
}

std::vector<std::unique_ptr<Target>> make_targets() {
    std::vector<std::unique_ptr<Target>> t;
    t.push_back(std::make_unique<GltfTarget>());
    t.push_back(std::make_unique<GlbTarget>());
    t.push_back(std::make_unique<TangentsTarget>());
    t.push_back(std::make_unique<Ktx2Target>());
    t.push_back(std::make_unique<CacheTarget>());
    t.push_back(std::make_unique<BasisTarget>());
    t.push_back(std::make_unique<MeshoptTarget>());
    t.push_back(std::make_unique<DracoTarget>());
    t.push_back(std::make_unique<ImageTarget>());
    t.push_back(std::make_unique<PoseTarget>());
    t.push_back(std::make_unique<ValidateTarget>());
    t.push_back(std::make_unique<MeshoptCodecTarget>());
    return t;
}

} // namespace sherpa::fuzz
