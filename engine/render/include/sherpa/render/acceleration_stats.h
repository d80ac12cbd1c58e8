#pragma once
// What the ray-tracing data of a scene is made of and how it is built: the statistics
// (BLAS per glTF mesh, TLAS, posed structures) and the build settings. Plain data with
// no Vulkan type, so that the renderer's public header (renderer.h) and its callers
// need no Vulkan header; the structures themselves are acceleration_structures.h.
#include <cstdint>
#include <string>
#include <vector>

namespace sherpa::render {

struct BlasStats {
    std::uint32_t mesh = 0; // glTF mesh (Mesh::group_id)
    std::string name;
    std::uint32_t geometries = 0, opaque_geometries = 0;
    std::uint64_t triangles = 0;
    // Every material single-sided (and bounding no volume): its instances let the
    // traversal cull back faces, and its opaque geometries need no any-hit (rt_plan.h).
    bool culls_back_faces = false;
    std::uint32_t first_geometry = 0; // its first GPUGeometryInfo record
    // False when every instance of the mesh skins or morphs: only their posed BLAS
    // (PosedStats) are built, and this one's sizes are 0.
    bool built = true;
    std::uint32_t batch = 0;
    // GPU time of its build (timestamps around it; the builds of a batch are
    // serialised by barriers so each is timed alone); negative without timestamps.
    double build_ms = -1.0;
    std::uint64_t build_bytes = 0;     // accelerationStructureSize as built
    std::uint64_t compacted_bytes = 0; // after compaction (= build_bytes when not compacted)
    std::uint64_t scratch_bytes = 0;   // buildScratchSize
};

struct TlasStats {
    std::uint64_t node_mesh_pairs = 0; // (node, glTF mesh) pairs with a BLAS
    std::uint64_t instances = 0;       // in the TLAS
    std::uint64_t deduplicated = 0;    // same mesh and identical world transform as another
    std::uint64_t mirrored = 0;        // negative determinant
    std::uint64_t hidden = 0;          // excluded: node hidden
    std::uint64_t non_finite = 0;      // excluded: NaN or infinite transform (with a warning)
    std::uint64_t bytes = 0, scratch_bytes = 0, instance_buffer_bytes = 0;
    double build_ms = -1.0; // the last build or refit
    // Full builds (the first on load, then whenever the instance set changed) and
    // refits (only transforms moved) so far.
    std::uint64_t builds = 0, refits = 0;
};

// The structures of meshes that skin or morph: per (node, glTF mesh) instance of
// one, posed copies of its moving vertices (positions, and the normals and tangents
// the hit shaders read) written by a compute pass from the frame's pose, and a BLAS
// over them, refitted (or rebuilt) when the pose changes. None for static scenes.
struct PosedStats {
    std::uint64_t blas = 0, geometries = 0, vertices = 0, triangles = 0;
    std::uint64_t world_space = 0;  // skinned instances: posed in world space
    std::uint64_t stream_bytes = 0; // the posed streams' buffer
    std::uint64_t blas_bytes = 0, scratch_bytes = 0;
    bool refit = true; // pose changes refit the BLAS (ALLOW_UPDATE), else rebuild them
    // Poses applied: 0 until the first (until then the TLAS leaves these instances out;
    // the Renderer applies the default pose on load).
    std::uint64_t updates = 0;
    std::uint64_t builds = 0, refits = 0;  // per posed BLAS, summed
    double pose_ms = -1.0, blas_ms = -1.0; // the last update: posing dispatches, BLAS builds
};

struct AccelerationStats {
    std::vector<BlasStats> blas;
    TlasStats tlas;
    PosedStats posed;
    std::uint32_t batches = 0;
    std::uint64_t scratch_budget = 0;
    std::uint64_t scratch_buffer_bytes = 0; // the largest batch's scratch buffer
    std::uint64_t geometry_records = 0, geometry_record_bytes = 0;
    double build_wall_ms = 0.0; // everything, on the CPU clock, waits included
    std::vector<std::string> warnings;

    std::uint64_t blas_triangles() const;
    std::uint64_t blas_build_bytes() const;
    std::uint64_t blas_compacted_bytes() const;
    // Device memory kept after the build: compacted BLAS, TLAS, instances, records,
    // and the posed streams, BLAS and scratch of moving meshes.
    std::uint64_t total_bytes() const;
};

struct AccelerationSettings {
    // The summed scratch of the BLAS built in one submission stays under this; a BLAS
    // that alone needs more is built alone.
    std::uint64_t scratch_budget = 64ull << 20;
    bool compact = true;
    // Posed BLAS (meshes that skin or morph) are refitted when the pose changes; false:
    // rebuilt (PREFER_FAST_BUILD, no ALLOW_UPDATE).
    bool refit_posed = true;
    // Per node: true excludes its instances (empty: every node shown). Through a
    // Renderer, FrameRequest::hidden_nodes (subtree rule applied) replaces it from the
    // first ray-traced frame on: the renderer's settings are the one source.
    std::vector<bool> hidden_nodes;
};

} // namespace sherpa::render
