#pragma once
// "Model no more than the scene needs": which attribute streams each primitive has,
// which its material actually reads, and what a GPU layout of only those would cost.
#include <array>
#include <cstdint>
#include <vector>

#include <sherpa/scene/scene.h>

namespace sherpa::scene {

struct PrimitiveUsage {
    std::uint32_t mesh_id = 0;
    std::uint32_t group_id = 0, primitive_index = 0;
    std::uint32_t material_id = 0;
    std::uint32_t instances = 0; // in the displayed scene
    std::uint64_t vertex_count = 0;
    std::array<bool, kVertexAttributeCount> present{}; // authored or generated
    std::array<bool, kVertexAttributeCount> used{};    // read by the material's shading
    std::uint64_t used_bytes = 0;                      // only the used streams
    std::uint64_t unified_bytes = 0; // 56-byte unified vertex (+ colour stream if present)
};

struct UsageReport {
    std::vector<PrimitiveUsage> primitives;
    // Totals over meshes the displayed scene instances.
    std::uint64_t used_bytes = 0, unified_bytes = 0;
    std::array<std::uint32_t, kVertexAttributeCount> meshes_using{};
};

// Which attributes `material` reads for shading, given what the mesh has.
std::array<bool, kVertexAttributeCount> attributes_used(const MaterialInstance& material,
                                                        const Mesh& mesh);
// The same for engine mesh `mesh` over every material it can show (its own and each
// KHR_materials_variants mapping's): what is uploaded, so a variant switch finds the
// streams its material reads.
std::array<bool, kVertexAttributeCount> mesh_attributes_used(const Scene& scene,
                                                             std::uint32_t mesh);
UsageReport build_usage_report(const Scene& scene);

} // namespace sherpa::scene
