#include "lab_scenes.h"

#include <cmath>

namespace sherpa::test {
namespace {

// Positions, normals and uv0 from the file; counts and bounds from the vertices.
void finish_uv_mesh(scene::Mesh& m) {
    m.provenance[std::size_t(scene::VertexAttribute::TexCoord0)] = scene::Provenance::Authored;
    m.provenance[std::size_t(scene::VertexAttribute::Tangent)] = scene::Provenance::Defaulted;
    m.provenance[std::size_t(scene::VertexAttribute::TexCoord1)] = scene::Provenance::Defaulted;
    m.provenance[std::size_t(scene::VertexAttribute::Color0)] = scene::Provenance::Defaulted;
    for (const scene::Vertex& v : m.vertices) m.local_bounds.expand(v.position);
    m.source_vertex_count = std::uint32_t(m.vertices.size());
    m.source_triangle_count = std::uint32_t(m.indices.size() / 3);
}

} // namespace

scene::Mesh mirrored_strip() {
    scene::Mesh m;
    m.name = "strip";
    // Columns x = 0, 1, 2; rows y = 0, 1. u = x on the left, 2 - x on the right.
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col) {
            scene::Vertex v;
            v.position = {float(col), float(row), 0.0f};
            v.normal = {0.0f, 0.0f, 1.0f};
            v.uv0 = {col <= 1 ? float(col) : 2.0f - float(col), 1.0f - float(row)};
            m.vertices.push_back(v);
        }
    // Quad corners a (bottom left), b (bottom right), c (top left), d (top right):
    // triangles a b d, a d c. Left quad: 0 1 4 3; right quad: 1 2 5 4.
    m.indices = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
    finish_uv_mesh(m);
    return m;
}

scene::Mesh wavy_grid(int n) {
    scene::Mesh m;
    m.name = "wavy";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float u = float(i) / float(n - 1), v = float(j) / float(n - 1);
            scene::Vertex vx;
            vx.position = {3.0f * u, v, 0.25f + 0.25f * std::sin(7.0f * u + 3.0f * v)};
            vx.normal = glm::normalize(glm::vec3(std::sin(5.0f * u), std::cos(4.0f * v), 1.3f));
            vx.uv0 = {2.0f * u, v};
            m.vertices.push_back(vx);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const std::uint32_t a = std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n),
                                d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    finish_uv_mesh(m);
    return m;
}

scene::Scene scene_of(std::vector<scene::Mesh> meshes) {
    scene::Scene s;
    s.source = "synthetic";
    s.materials.emplace_back();
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        meshes[i].group_id = std::uint32_t(i);
        scene::MeshInstance inst;
        inst.mesh_id = std::uint32_t(i);
        inst.world_bounds = meshes[i].local_bounds;
        s.instances.push_back(inst);
        s.bounds.expand(meshes[i].local_bounds);
    }
    s.meshes = std::move(meshes);
    return s;
}

} // namespace sherpa::test
