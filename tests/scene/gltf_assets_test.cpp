// Every real sample model: counts equal what the glTF JSON states (computed here
// independently from the JSON, not through tinygltf), and world bounds follow the
// node transforms.
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

using nlohmann::json;

namespace {

struct JsonCounts {
    std::uint64_t scenes, nodes, meshes, primitives, materials, textures, images, samplers, lights,
        cameras;
    std::uint64_t vertices = 0, triangles = 0, instances = 0, drawable_instances = 0;
};

std::uint64_t size_of(const json& doc, const char* key) {
    return doc.contains(key) ? doc[key].size() : 0;
}

std::uint64_t primitive_triangles(const json& doc, const json& prim) {
    const int mode = prim.value("mode", 4);
    const std::uint64_t n =
        prim.contains("indices")
            ? doc["accessors"][prim["indices"].get<int>()]["count"].get<std::uint64_t>()
            : doc["accessors"][prim["attributes"]["POSITION"].get<int>()]["count"]
                  .get<std::uint64_t>();
    if (mode == 4) return n / 3;
    if (mode == 5 || mode == 6) return n >= 3 ? n - 2 : 0;
    return 0;
}

JsonCounts counts_from_json(const json& doc) {
    JsonCounts c{size_of(doc, "scenes"),
                 size_of(doc, "nodes"),
                 size_of(doc, "meshes"),
                 0,
                 size_of(doc, "materials"),
                 size_of(doc, "textures"),
                 size_of(doc, "images"),
                 size_of(doc, "samplers"),
                 0,
                 size_of(doc, "cameras")};
    if (doc.contains("extensions") && doc["extensions"].contains("KHR_lights_punctual"))
        c.lights = doc["extensions"]["KHR_lights_punctual"]["lights"].size();
    std::vector<std::uint64_t> drawable_prims, all_prims;
    for (const auto& mesh : doc.value("meshes", json::array())) {
        std::uint64_t drawable = 0;
        for (const auto& prim : mesh["primitives"]) {
            ++c.primitives;
            c.vertices += doc["accessors"][prim["attributes"]["POSITION"].get<int>()]["count"]
                              .get<std::uint64_t>();
            const auto tris = primitive_triangles(doc, prim);
            c.triangles += tris;
            drawable += tris > 0 ? 1 : 0;
        }
        drawable_prims.push_back(drawable);
        all_prims.push_back(mesh["primitives"].size());
    }
    const int scene = doc.value("scene", 0);
    std::vector<int> stack = doc["scenes"][scene]["nodes"].get<std::vector<int>>();
    while (!stack.empty()) {
        const json& node = doc["nodes"][stack.back()];
        stack.pop_back();
        if (node.contains("mesh")) {
            c.drawable_instances += drawable_prims[node["mesh"].get<int>()];
            c.instances += all_prims[node["mesh"].get<int>()];
        }
        for (int child : node.value("children", std::vector<int>{})) stack.push_back(child);
    }
    return c;
}

class EveryAsset : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAsset, CountsMatchTheJson) {
    const std::string path = sherpa::test::gltf_asset(GetParam());
    const JsonCounts want = counts_from_json(sherpa::test::read_json(path));
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    const sherpa::scene::SourceCounts& got = r.scene->counts;
    EXPECT_EQ(got.scenes, want.scenes);
    EXPECT_EQ(got.nodes, want.nodes);
    EXPECT_EQ(got.meshes, want.meshes);
    EXPECT_EQ(got.primitives, want.primitives);
    EXPECT_EQ(got.materials, want.materials);
    EXPECT_EQ(got.textures, want.textures);
    EXPECT_EQ(got.images, want.images);
    EXPECT_EQ(got.samplers, want.samplers);
    EXPECT_EQ(got.lights, want.lights);
    EXPECT_EQ(got.cameras, want.cameras);
    EXPECT_EQ(got.vertices, want.vertices);
    EXPECT_EQ(got.triangles, want.triangles);
    EXPECT_EQ(r.scene->node_primitive_pairs(), want.instances);
    EXPECT_EQ(r.scene->instances.size(), want.drawable_instances);
    ASSERT_TRUE(r.scene->bounds.valid());
    EXPECT_TRUE(sherpa::core::is_finite(r.scene->bounds.min) &&
                sherpa::core::is_finite(r.scene->bounds.max));
    EXPECT_EQ(r.scene->primitives.size(), want.primitives);
}

TEST_P(EveryAsset, MeshesAreWellFormed) {
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene(sherpa::test::gltf_asset(GetParam()));
    ASSERT_TRUE(r) << r.error;
    for (const sherpa::scene::Mesh& m : r.scene->meshes) {
        ASSERT_EQ(m.indices.size() % 3, 0u);
        ASSERT_GT(m.indices.size(), 0u);
        for (std::uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
        ASSERT_TRUE(m.colors.empty() || m.colors.size() == m.vertices.size());
        ASSERT_LT(m.material_id, r.scene->materials.size());
        ASSERT_TRUE(m.local_bounds.valid());
        EXPECT_EQ(m.provenance_of(sherpa::scene::VertexAttribute::Position),
                  sherpa::scene::Provenance::Authored);
        EXPECT_NE(m.provenance_of(sherpa::scene::VertexAttribute::Normal),
                  sherpa::scene::Provenance::Defaulted);
    }
    for (const auto& inst : r.scene->instances) {
        ASSERT_LT(inst.mesh_id, r.scene->meshes.size());
        EXPECT_EQ(inst.material_id, r.scene->meshes[inst.mesh_id].material_id);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedAssets, EveryAsset,
                         ::testing::ValuesIn(sherpa::test::all_gltf_models()),
                         [](const auto& param_info) { return param_info.param; });

TEST(SharedAssets, ArePresent) {
    // Guards against a silently empty parameterised suite.
    EXPECT_GE(sherpa::test::all_gltf_models().size(), 20u)
        << "assets missing under " << sherpa::test::assets_dir();
}

// Independent world-bounds computation from the JSON: node matrices or TRS composed
// down the hierarchy, applied to the 8 corners of each POSITION accessor's min/max.
glm::mat4 json_local(const json& node) {
    if (node.contains("matrix")) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = node["matrix"][i].get<float>();
        return m;
    }
    glm::mat4 m(1.0f);
    if (node.contains("translation"))
        m = glm::translate(m, {node["translation"][0].get<float>(),
                               node["translation"][1].get<float>(),
                               node["translation"][2].get<float>()});
    if (node.contains("rotation")) {
        const auto& q = node["rotation"];
        m *= glm::mat4_cast(
            glm::quat(q[3].get<float>(), q[0].get<float>(), q[1].get<float>(), q[2].get<float>()));
    }
    if (node.contains("scale"))
        m = glm::scale(m, {node["scale"][0].get<float>(), node["scale"][1].get<float>(),
                           node["scale"][2].get<float>()});
    return m;
}

void expect_bounds_follow_node_transforms(const std::string& name) {
    const std::string path = sherpa::test::gltf_asset(name);
    const json doc = sherpa::test::read_json(path);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    std::vector<std::pair<int, glm::mat4>> stack;
    for (int root : doc["scenes"][doc.value("scene", 0)]["nodes"])
        stack.emplace_back(root, json_local(doc["nodes"][root]));
    while (!stack.empty()) {
        const auto [id, world] = stack.back();
        stack.pop_back();
        const json& node = doc["nodes"][id];
        if (node.contains("mesh"))
            for (const auto& prim : doc["meshes"][node["mesh"].get<int>()]["primitives"]) {
                const json& acc = doc["accessors"][prim["attributes"]["POSITION"].get<int>()];
                for (int c = 0; c < 8; ++c) {
                    const glm::vec3 p{acc["min"][0].get<float>(), acc["min"][1].get<float>(),
                                      acc["min"][2].get<float>()};
                    const glm::vec3 q{acc["max"][0].get<float>(), acc["max"][1].get<float>(),
                                      acc["max"][2].get<float>()};
                    const glm::vec3 corner{(c & 1) ? q.x : p.x, (c & 2) ? q.y : p.y,
                                           (c & 4) ? q.z : p.z};
                    const glm::vec3 w = glm::vec3(world * glm::vec4(corner, 1.0f));
                    lo = glm::min(lo, w);
                    hi = glm::max(hi, w);
                }
            }
        for (int child : node.value("children", std::vector<int>{}))
            stack.emplace_back(child, world * json_local(doc["nodes"][child]));
    }
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    const float tol = 1e-4f * glm::length(hi - lo);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(r.scene->bounds.min[k], lo[k], tol) << name << " axis " << k;
        EXPECT_NEAR(r.scene->bounds.max[k], hi[k], tol) << name << " axis " << k;
    }
}

TEST(WorldBounds, OrientationTestFollowsNodeTransforms) {
    expect_bounds_follow_node_transforms("OrientationTest");
}
TEST(WorldBounds, TwoCylinderEngineFollowsNodeTransforms) {
    expect_bounds_follow_node_transforms("2CylinderEngine");
}

TEST(Scenes, DefaultSceneAndSelection) {
    sherpa::scene::LoadResult r =
        sherpa::scene::load_scene(sherpa::test::gltf_asset("OrientationTest"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->displayed_scene, 0);
    std::string error;
    EXPECT_FALSE(sherpa::scene::select_scene(*r.scene, 5, error));
    EXPECT_NE(error.find("out of range"), std::string::npos);
    EXPECT_EQ(r.scene->instances.size(), 13u)
        << "a failed selection must leave the scene unchanged";
    sherpa::scene::LoadOptions opt;
    opt.scene_index = 1;
    EXPECT_FALSE(sherpa::scene::load_scene(sherpa::test::gltf_asset("OrientationTest"), opt));
}

} // namespace
