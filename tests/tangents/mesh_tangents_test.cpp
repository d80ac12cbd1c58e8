// Writing per-corner tangents into meshes (vertex splitting) and the glTF rule for
// which meshes of a scene get generated tangents.
#include <stdexcept>

#include <gtest/gtest.h>

#include <sherpa/scene/mesh_tangents.h>

namespace sherpa {
namespace {

scene::Vertex vertex(glm::vec3 p, glm::vec2 uv0, glm::vec2 uv1 = {}) {
    scene::Vertex v;
    v.position = p;
    v.uv0 = uv0;
    v.uv1 = uv1;
    return v;
}

// Two triangles sharing the edge 1-2; uv0 mirrors across it, uv1 does not.
scene::Mesh mirrored_pair() {
    scene::Mesh m;
    m.vertices = {vertex({0, 0, 0}, {1, 1}, {0, 1}), vertex({1, 0, 0}, {0, 1}, {1, 1}),
                  vertex({1, 1, 0}, {0, 0}, {1, 0}), vertex({2, 0, 0}, {1, 1}, {2, 1})};
    m.indices = {0, 1, 2, 1, 3, 2};
    m.colors = {glm::vec4(1), glm::vec4(2), glm::vec4(3), glm::vec4(4)};
    m.provenance[static_cast<std::size_t>(scene::VertexAttribute::Tangent)] =
        scene::Provenance::Defaulted;
    return m;
}

TEST(MeshTangents, ApplySplitsOnlyDisagreeingVertices) {
    scene::Mesh m = mirrored_pair();
    const glm::vec4 left(-1, 0, 0, -1), right(1, 0, 0, 1);
    const std::vector<glm::vec4> corners = {left, left, left, right, right, right};
    EXPECT_EQ(scene::apply_corner_tangents(m, corners), 2u); // vertices 1 and 2
    ASSERT_EQ(m.vertices.size(), 6u);
    ASSERT_EQ(m.colors.size(), 6u);
    for (std::size_t c = 0; c < m.indices.size(); ++c)
        EXPECT_EQ(m.vertices[m.indices[c]].tangent, corners[c]);
    EXPECT_EQ(m.vertices[m.indices[3]].position, glm::vec3(1, 0, 0));
    EXPECT_EQ(m.colors[m.indices[3]], glm::vec4(2));
    // Applying the same tangents again splits nothing more.
    EXPECT_EQ(scene::apply_corner_tangents(m, corners), 0u);
}

TEST(MeshTangents, ApplyReusesCopiesWithEqualTangents) {
    scene::Mesh m;
    m.vertices = {vertex({0, 0, 0}, {}), vertex({1, 0, 0}, {}), vertex({0, 1, 0}, {})};
    m.indices = {0, 1, 2, 0, 2, 1, 0, 1, 2};
    const glm::vec4 a(1, 0, 0, 1), b(0, 1, 0, 1);
    EXPECT_EQ(scene::apply_corner_tangents(m, std::vector<glm::vec4>{a, a, a, b, b, b, b, b, b}),
              3u);
    EXPECT_EQ(m.indices[6], m.indices[3]);
}

TEST(MeshTangents, ApplyRejectsWrongCornerCount) {
    scene::Mesh m = mirrored_pair();
    EXPECT_THROW(scene::apply_corner_tangents(m, std::vector<glm::vec4>(5)), std::invalid_argument);
}

TEST(MeshTangents, GenerateUsesTheRequestedUvSet) {
    scene::Mesh by_uv0 = mirrored_pair(), by_uv1 = mirrored_pair();
    const scene::MeshTangentReport r0 =
        scene::generate_mesh_tangents(by_uv0, 0, scene::TangentMethod::MikkTSpace);
    const scene::MeshTangentReport r1 =
        scene::generate_mesh_tangents(by_uv1, 1, scene::TangentMethod::MikkTSpace);
    EXPECT_EQ(r0.split_vertices, 2u); // mirror seam along the shared edge
    EXPECT_EQ(r1.split_vertices, 0u);
    EXPECT_EQ(by_uv1.provenance_of(scene::VertexAttribute::Tangent), scene::Provenance::Generated);
    for (const scene::Vertex& v : by_uv1.vertices) EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    scene::Mesh by_uv3 = mirrored_pair();
    const scene::MeshTangentReport r3 =
        scene::generate_mesh_tangents(by_uv3, 3, scene::TangentMethod::MikkTSpace);
    EXPECT_EQ(r3.tex_coord, 0u);
    EXPECT_FALSE(r3.reason.empty());
}

scene::Scene scene_of(bool normal_texture, scene::Provenance tangent, std::uint32_t tex_coord = 0) {
    scene::Scene s;
    s.meshes.push_back(mirrored_pair());
    s.meshes[0].provenance[static_cast<std::size_t>(scene::VertexAttribute::Tangent)] = tangent;
    s.materials.emplace_back();
    if (normal_texture) s.materials[0].normal = scene::TextureSlot{0, tex_coord, {}};
    return s;
}

TEST(MeshTangents, SceneRuleFollowsGltf) {
    scene::Scene needs = scene_of(true, scene::Provenance::Defaulted, 1);
    scene::SceneTangentReport r = scene::generate_scene_tangents(needs, {});
    EXPECT_EQ(r.generated_meshes, 1u);
    EXPECT_EQ(r.meshes[0].tex_coord, 1u);
    EXPECT_EQ(r.split_vertices, 0u);

    scene::Scene no_texture = scene_of(false, scene::Provenance::Defaulted);
    EXPECT_EQ(scene::generate_scene_tangents(no_texture, {}).generated_meshes, 0u);

    scene::Scene authored = scene_of(true, scene::Provenance::Authored);
    authored.meshes[0].vertices[0].tangent = glm::vec4(0, 0, 1, 1);
    EXPECT_EQ(scene::generate_scene_tangents(authored, {}).generated_meshes, 0u);
    EXPECT_EQ(authored.meshes[0].vertices[0].tangent, glm::vec4(0, 0, 1, 1));
    EXPECT_EQ(authored.meshes[0].provenance_of(scene::VertexAttribute::Tangent),
              scene::Provenance::Authored);

    scene::SceneTangentOptions regenerate;
    regenerate.regenerate = true;
    r = scene::generate_scene_tangents(authored, regenerate);
    EXPECT_EQ(r.generated_meshes, 1u);
    EXPECT_EQ(r.meshes[0].reason, "regenerated");
    EXPECT_EQ(authored.meshes[0].provenance_of(scene::VertexAttribute::Tangent),
              scene::Provenance::Generated);
}

} // namespace
} // namespace sherpa
