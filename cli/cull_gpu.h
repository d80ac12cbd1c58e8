#pragma once
// The GPU-driven path of `sherpa-cli cull --method gpu`.
#include <string>
#include <utility>
#include <vector>

#include <sherpa/scene/culling_passes.h>

namespace sherpa::cli {

// Culls each named frustum on the GPU (p-vertex test, the camera pass over every
// instance, cascades over the shadow pass's casters) and checks each against the
// CPU p-vertex result `cpu` of the same pass. Returns false with `error` set when
// no Vulkan device can be used.
bool gpu_cull_passes(const Scene& scene, const std::vector<std::pair<std::string, Frustum>>& frusta,
                     const std::vector<PassResult>& cpu, std::vector<PassResult>& out,
                     std::string& error);

} // namespace sherpa::cli
