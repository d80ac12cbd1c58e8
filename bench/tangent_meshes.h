#pragma once
// Meshes for the tangent benchmark and accuracy report: a large synthetic torus and the
// sample models, as plain indexed arrays.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/scene/tangents.h>

#include "gltf_primitives.h"

namespace sherpa::bench {

struct BenchMesh {
    std::string name;
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> authored; // per vertex, empty if none
    std::vector<std::uint32_t> indices;
    std::size_t triangles() const { return indices.size() / 3; }
    scene::TangentInput input() const { return {positions, normals, uvs, indices}; }
};

// A torus of rings x segments quads (2 triangles each) with a uv seam where u wraps and a
// mirrored uv island on the inner half, so welding, seams and orientation all matter.
inline BenchMesh make_torus(std::uint32_t rings, std::uint32_t segments) {
    BenchMesh m;
    m.name = "torus-" + std::to_string(2ull * rings * segments);
    const float major = 1.0f, minor = 0.35f, pi2 = 6.2831853f;
    for (std::uint32_t r = 0; r <= rings; ++r)
        for (std::uint32_t s = 0; s <= segments; ++s) {
            const float u = float(r) / rings, v = float(s) / segments;
            const float a = u * pi2, b = v * pi2;
            const glm::vec3 n(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
            const glm::vec3 center(std::cos(a) * major, std::sin(a) * major, 0.0f);
            m.positions.push_back(center + minor * n);
            m.normals.push_back(n);
            // Inner half (cos b < 0) mirrors u: a mirror seam along two rings of the tube.
            m.uvs.push_back({std::cos(b) < 0.0f ? 1.0f - u : u, v});
        }
    const std::uint32_t row = segments + 1;
    for (std::uint32_t r = 0; r < rings; ++r)
        for (std::uint32_t s = 0; s < segments; ++s) {
            const std::uint32_t a = r * row + s, b = a + row;
            m.indices.insert(m.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
        }
    return m;
}

// One BenchMesh per sample model: its triangle primitives with normals and uvs,
// concatenated (named by the model). Authored tangents are kept only when every
// primitive has them.
inline std::vector<BenchMesh> load_sample_meshes(const std::string& assets_dir) {
    std::vector<BenchMesh> out;
    for (const std::string& name : tools::sample_models(assets_dir)) {
        BenchMesh m;
        m.name = name;
        bool all_authored = true;
        for (const tools::GltfPrimitive& p :
             tools::read_gltf_primitives(tools::sample_model_path(assets_dir, name))) {
            if (p.normals.empty() || p.uvs.empty() || p.indices.empty()) continue;
            const auto base = static_cast<std::uint32_t>(m.positions.size());
            m.positions.insert(m.positions.end(), p.positions.begin(), p.positions.end());
            m.normals.insert(m.normals.end(), p.normals.begin(), p.normals.end());
            m.uvs.insert(m.uvs.end(), p.uvs.begin(), p.uvs.end());
            all_authored = all_authored && !p.tangents.empty();
            if (!p.tangents.empty())
                m.authored.insert(m.authored.end(), p.tangents.begin(), p.tangents.end());
            for (std::uint32_t i : p.indices) m.indices.push_back(base + i);
        }
        if (!all_authored) m.authored.clear();
        if (!m.indices.empty()) out.push_back(std::move(m));
    }
    return out;
}

} // namespace sherpa::bench
