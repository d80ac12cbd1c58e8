#pragma once
// Progress and cancellation of load_scene's stages (private to the scene layer).
#include <sherpa/scene/scene_loader.h>

namespace sherpa::scene::detail {

// Reports `stage` as started; false when the load has been cancelled.
bool begin_stage(const LoadOptions& options, LoadStage stage, std::size_t total = 1);
// Reports `stage` as done; false when the load has been cancelled.
bool end_stage(const LoadOptions& options, LoadStage stage, std::size_t total = 1);
// The Tangents stage (generation per the options, warnings, per-mesh progress);
// false when cancelled (the scene is then half done and must be dropped).
bool tangent_stage(Scene& scene, const LoadOptions& options);
LoadResult cancelled_result();

} // namespace sherpa::scene::detail
