#pragma once
// What a scene load fixes (Renderer::load): which vertex streams are uploaded, how
// material slots without a usable texture are drawn, and which nodes are hidden. What a
// frame asks (camera, view, overlays, pose, highlight) is a FrameRequest
// (frame_request.h). No Vulkan types.
#include <memory>
#include <vector>

#include <sherpa/render/load_settings.h>

namespace sherpa::render {

struct SceneSetup {
    // The vertex streams uploaded: what the materials read, or every stream (debug
    // views of streams no material reads; needs_all_streams() of the frames to come).
    // A change takes a new load().
    StreamPolicy streams = StreamPolicy::UsedByMaterials;
    // Material slots whose texture is missing or undecodable. A change takes a new load().
    MissingTextures missing_textures = MissingTextures::Checker;
    // Nodes hidden (per node index, true: hidden; null or empty: every node shown). A
    // hidden node hides its subtree (hidden_subtrees(), sherpa/scene/visibility.h): its
    // instances are drawn by no pass (camera on every cull path, shadow cascades,
    // prepass, overlays, highlight) and left out of the ray tracer's TLAS. Changed
    // after a load with Renderer::set_hidden_nodes(): the renderer compares the mask
    // with the one it applied last before each frame, and only a change costs (GPU
    // cullers rebuilt, cached cascades redrawn, TLAS rebuilt).
    std::shared_ptr<const std::vector<bool>> hidden_nodes;
};

} // namespace sherpa::render
