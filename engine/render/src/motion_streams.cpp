#include "motion_streams.h"

#include <cstring>

namespace sherpa::render {

namespace {

// Appends `count` elements of `size` bytes (16-byte aligned start); returns the offset.
template <typename Fill>
VkDeviceAddress append(std::vector<std::uint8_t>& out, std::size_t count, std::size_t size,
                       Fill&& fill) {
    out.resize((out.size() + 15) & ~std::size_t(15));
    const std::size_t at = out.size();
    out.resize(at + count * size);
    for (std::size_t i = 0; i < count; ++i) fill(i, out.data() + at + i * size);
    return at;
}

} // namespace

MotionStreams build_motion_streams(const scene::Scene& scene, const std::vector<bool>& uploaded) {
    MotionStreams out;
    out.record_of_mesh.assign(scene.meshes.size(), -1);
    for (const scene::PrimitiveInfo& prim : scene.primitives) {
        if (prim.motion < 0 || prim.engine_mesh < 0) continue;
        const auto mesh_index = static_cast<std::size_t>(prim.engine_mesh);
        if (mesh_index >= uploaded.size() || !uploaded[mesh_index]) continue;
        const scene::Mesh& mesh = scene.meshes[mesh_index];
        const scene::PrimitiveMotion& m = scene.motions[static_cast<std::size_t>(prim.motion)];
        const std::size_t vc = mesh.vertices.size();
        auto source = [&](std::size_t v) -> std::size_t {
            return mesh.source_vertex.empty() ? v : mesh.source_vertex[v];
        };
        GPUMotionMesh r{};
        r.vertex_count = static_cast<std::uint32_t>(vc);
        if (m.skinned()) {
            const std::uint32_t n = m.influences, sets = (n + 3) / 4;
            r.influence_sets = sets;
            r.flags |= kMotionSkin;
            // Per vertex and set: four 16-bit joints in two uints, four weights.
            r.joints = append(out.bytes, vc * sets, 8, [&](std::size_t e, std::uint8_t* dst) {
                const std::size_t v = source(e / sets), s = e % sets;
                std::uint32_t packed[2] = {0, 0};
                // Unweighted slots read joint 0: their index may lie past the skin.
                for (std::uint32_t k = 0; k < 4 && 4 * s + k < n; ++k)
                    if (m.weights[v * n + 4 * s + k] != 0.0f)
                        packed[k / 2] |= std::uint32_t(m.joints[v * n + 4 * s + k])
                                         << (16 * (k % 2));
                std::memcpy(dst, packed, 8);
            });
            r.weights = append(out.bytes, vc * sets, 16, [&](std::size_t e, std::uint8_t* dst) {
                const std::size_t v = source(e / sets), s = e % sets;
                float w[4] = {0, 0, 0, 0};
                for (std::uint32_t k = 0; k < 4 && 4 * s + k < n; ++k)
                    w[k] = m.weights[v * n + 4 * s + k];
                std::memcpy(dst, w, 16);
            });
        }
        r.target_count = static_cast<std::uint32_t>(m.targets.size());
        // One stream per attribute any target moves (zeros where a target does not).
        auto morph = [&](std::vector<glm::vec3> scene::MorphTarget::*attr, std::uint32_t bit,
                         VkDeviceAddress& address) {
            bool any = false;
            for (const scene::MorphTarget& t : m.targets) any = any || !(t.*attr).empty();
            if (!any) return;
            r.flags |= bit;
            address =
                append(out.bytes, vc * m.targets.size(), 12, [&](std::size_t e, std::uint8_t* dst) {
                    const auto& d = m.targets[e / vc].*attr;
                    const std::size_t v = source(e % vc);
                    const glm::vec3 delta = v < d.size() ? d[v] : glm::vec3(0.0f);
                    std::memcpy(dst, &delta, 12);
                });
        };
        morph(&scene::MorphTarget::position, kMotionMorphPositions, r.morph_positions);
        morph(&scene::MorphTarget::normal, kMotionMorphNormals, r.morph_normals);
        morph(&scene::MorphTarget::tangent, kMotionMorphTangents, r.morph_tangents);
        out.record_of_mesh[mesh_index] = static_cast<std::int32_t>(out.records.size());
        out.records.push_back(r);
    }
    return out;
}

} // namespace sherpa::render
