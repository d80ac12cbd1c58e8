#include "lab_scenes.h"

namespace sherpa::test {

Mesh mirrored_strip() {
    Mesh m;
    m.name = "strip";
    // Columns x = 0, 1, 2; rows y = 0, 1. u = x on the left, 2 - x on the right.
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col) {
            Vertex v;
            v.position = {float(col), float(row), 0.0f};
            v.normal = {0.0f, 0.0f, 1.0f};
            v.uv0 = {col <= 1 ? float(col) : 2.0f - float(col), 1.0f - float(row)};
            m.vertices.push_back(v);
        }
    // Quad corners a (bottom left), b (bottom right), c (top left), d (top right):
    // triangles a b d, a d c. Left quad: 0 1 4 3; right quad: 1 2 5 4.
    m.indices = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
    m.provenance[std::size_t(VertexAttribute::TexCoord0)] = Provenance::Authored;
    m.provenance[std::size_t(VertexAttribute::Tangent)] = Provenance::Defaulted;
    m.provenance[std::size_t(VertexAttribute::TexCoord1)] = Provenance::Defaulted;
    m.provenance[std::size_t(VertexAttribute::Color0)] = Provenance::Defaulted;
    for (const Vertex& v : m.vertices) m.local_bounds.expand(v.position);
    m.source_vertex_count = std::uint32_t(m.vertices.size());
    m.source_triangle_count = std::uint32_t(m.indices.size() / 3);
    return m;
}

Scene scene_of(std::vector<Mesh> meshes) {
    Scene s;
    s.source = "synthetic";
    s.materials.emplace_back();
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        meshes[i].group_id = std::uint32_t(i);
        MeshInstance inst;
        inst.mesh_id = std::uint32_t(i);
        inst.world_bounds = meshes[i].local_bounds;
        s.instances.push_back(inst);
        s.bounds.expand(meshes[i].local_bounds);
    }
    s.meshes = std::move(meshes);
    return s;
}

} // namespace sherpa::test
