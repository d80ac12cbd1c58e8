#pragma once
// The skinning and morph streams of the meshes that move, in engine-vertex order
// (the importer keeps them in the file's vertex order; Mesh::source_vertex maps
// split or unwelded vertices back). Meshes without motion get nothing.
#include <cstdint>
#include <vector>

#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/scene.h>

namespace sherpa::render {

struct MotionStreams {
    std::vector<std::uint8_t> bytes; // every stream, each 16-byte aligned
    // One per moving mesh; its addresses are byte offsets into `bytes` until the
    // upload rebases them onto the buffer's device address.
    std::vector<GPUMotionMesh> records;
    std::vector<std::int32_t> record_of_mesh; // per engine mesh: index into records, -1: static
};

// Streams of every engine mesh in `uploaded` (those drawn) whose primitive skins or
// morphs (PrimitiveInfo::motion).
MotionStreams build_motion_streams(const scene::Scene& scene, const std::vector<bool>& uploaded);

} // namespace sherpa::render
