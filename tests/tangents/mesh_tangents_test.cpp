// Writing per-corner tangents into meshes (vertex splitting) and the glTF rule for
// which meshes of a scene get generated tangents.
#include <stdexcept>

#include <gtest/gtest.h>

#include <sherpa/scene/mesh_tangents.h>

namespace sherpa {
namespace {

Vertex vertex(glm::vec3 p, glm::vec2 uv0, glm::vec2 uv1 = {}) {
    Vertex v;
    v.position = p;
    v.uv0 = uv0;
    v.uv1 = uv1;
    return v;
}

// Two triangles sharing the edge 1-2; uv0 mirrors across it, uv1 does not.
Mesh mirrored_pair() {
    Mesh m;
    m.vertices = {vertex({0, 0, 0}, {1, 1}, {0, 1}), vertex({1, 0, 0}, {0, 1}, {1, 1}),
                  vertex({1, 1, 0}, {0, 0}, {1, 0}), vertex({2, 0, 0}, {1, 1}, {2, 1})};
    m.indices = {0, 1, 2, 1, 3, 2};
    m.colors = {glm::vec4(1), glm::vec4(2), glm::vec4(3), glm::vec4(4)};
    m.provenance[static_cast<std::size_t>(VertexAttribute::Tangent)] = Provenance::Defaulted;
    return m;
}

TEST(MeshTangents, ApplySplitsOnlyDisagreeingVertices) {
    Mesh m = mirrored_pair();
    const glm::vec4 left(-1, 0, 0, -1), right(1, 0, 0, 1);
    const std::vector<glm::vec4> corners = {left, left, left, right, right, right};
    EXPECT_EQ(apply_corner_tangents(m, corners), 2u); // vertices 1 and 2
    ASSERT_EQ(m.vertices.size(), 6u);
    ASSERT_EQ(m.colors.size(), 6u);
    for (std::size_t c = 0; c < m.indices.size(); ++c)
        EXPECT_EQ(m.vertices[m.indices[c]].tangent, corners[c]);
    EXPECT_EQ(m.vertices[m.indices[3]].position, glm::vec3(1, 0, 0));
    EXPECT_EQ(m.colors[m.indices[3]], glm::vec4(2));
    // Applying the same tangents again splits nothing more.
    EXPECT_EQ(apply_corner_tangents(m, corners), 0u);
}

TEST(MeshTangents, ApplyReusesCopiesWithEqualTangents) {
    Mesh m;
    m.vertices = {vertex({0, 0, 0}, {}), vertex({1, 0, 0}, {}), vertex({0, 1, 0}, {})};
    m.indices = {0, 1, 2, 0, 2, 1, 0, 1, 2};
    const glm::vec4 a(1, 0, 0, 1), b(0, 1, 0, 1);
    EXPECT_EQ(apply_corner_tangents(m, std::vector<glm::vec4>{a, a, a, b, b, b, b, b, b}), 3u);
    EXPECT_EQ(m.indices[6], m.indices[3]);
}

TEST(MeshTangents, ApplyRejectsWrongCornerCount) {
    Mesh m = mirrored_pair();
    EXPECT_THROW(apply_corner_tangents(m, std::vector<glm::vec4>(5)), std::invalid_argument);
}

TEST(MeshTangents, GenerateUsesTheRequestedUvSet) {
    Mesh by_uv0 = mirrored_pair(), by_uv1 = mirrored_pair();
    const MeshTangentReport r0 = generate_mesh_tangents(by_uv0, 0, TangentMethod::MikkTSpace);
    const MeshTangentReport r1 = generate_mesh_tangents(by_uv1, 1, TangentMethod::MikkTSpace);
    EXPECT_EQ(r0.split_vertices, 2u); // mirror seam along the shared edge
    EXPECT_EQ(r1.split_vertices, 0u);
    EXPECT_EQ(by_uv1.provenance_of(VertexAttribute::Tangent), Provenance::Generated);
    for (const Vertex& v : by_uv1.vertices) EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    Mesh by_uv3 = mirrored_pair();
    const MeshTangentReport r3 = generate_mesh_tangents(by_uv3, 3, TangentMethod::MikkTSpace);
    EXPECT_EQ(r3.tex_coord, 0u);
    EXPECT_FALSE(r3.reason.empty());
}

Scene scene_of(bool normal_texture, Provenance tangent, std::uint32_t tex_coord = 0) {
    Scene s;
    s.meshes.push_back(mirrored_pair());
    s.meshes[0].provenance[static_cast<std::size_t>(VertexAttribute::Tangent)] = tangent;
    s.materials.emplace_back();
    if (normal_texture) s.materials[0].normal = TextureSlot{0, tex_coord, {}};
    return s;
}

TEST(MeshTangents, SceneRuleFollowsGltf) {
    Scene needs = scene_of(true, Provenance::Defaulted, 1);
    SceneTangentReport r = generate_scene_tangents(needs, {});
    EXPECT_EQ(r.generated_meshes, 1u);
    EXPECT_EQ(r.meshes[0].tex_coord, 1u);
    EXPECT_EQ(r.split_vertices, 0u);

    Scene no_texture = scene_of(false, Provenance::Defaulted);
    EXPECT_EQ(generate_scene_tangents(no_texture, {}).generated_meshes, 0u);

    Scene authored = scene_of(true, Provenance::Authored);
    authored.meshes[0].vertices[0].tangent = glm::vec4(0, 0, 1, 1);
    EXPECT_EQ(generate_scene_tangents(authored, {}).generated_meshes, 0u);
    EXPECT_EQ(authored.meshes[0].vertices[0].tangent, glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(authored.meshes[0].provenance_of(VertexAttribute::Tangent), Provenance::Authored);

    SceneTangentOptions regenerate;
    regenerate.regenerate = true;
    r = generate_scene_tangents(authored, regenerate);
    EXPECT_EQ(r.generated_meshes, 1u);
    EXPECT_EQ(r.meshes[0].reason, "regenerated");
    EXPECT_EQ(authored.meshes[0].provenance_of(VertexAttribute::Tangent), Provenance::Generated);
}

} // namespace
} // namespace sherpa
