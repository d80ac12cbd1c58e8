// EXT_mesh_gpu_instancing on hand-made files (tests/data/make_instancing_cases.py):
// each row is an instance at node world x T x R x S; what a file gets wrong is
// named with its JSON path and drawn as well as it can be. The gltfpack and
// gltf-transform files: tests/scene/instanced_corpus_test.cpp.
#include "load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace {

namespace test = sherpa::test;

sherpa::scene::LoadResult load(const char* file) {
    return sherpa::scene::load_scene((test::data_dir() / file).string());
}

bool has_warning(const sherpa::scene::Scene& s, const std::string& fragment) {
    return std::any_of(s.warnings.begin(), s.warnings.end(),
                       [&](const std::string& w) { return w.find(fragment) != std::string::npos; });
}

std::string all_warnings(const sherpa::scene::Scene& s) {
    std::string out;
    for (const auto& w : s.warnings) out += w + "\n";
    return out;
}

bool inside(const sherpa::core::Aabb& b, glm::vec3 p) {
    const glm::vec3 pad(1e-5f);
    return b.valid() && glm::all(glm::greaterThanEqual(p, b.min - pad)) &&
           glm::all(glm::lessThanEqual(p, b.max + pad));
}

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}

TEST(GpuInstancing, EachRowIsAnInstanceAtNodeWorldTimesTRS) {
    const auto r = load("instancing_basic.gltf");
    ASSERT_TRUE(r) << r.error;
    const sherpa::scene::Scene& s = *r.scene;
    EXPECT_EQ(all_warnings(s).find("EXT_mesh_gpu_instancing"), std::string::npos)
        << all_warnings(s);
    ASSERT_TRUE(s.nodes[0].instancing);
    EXPECT_EQ(s.nodes[0].instancing->file_rows, 3u);
    ASSERT_EQ(s.instances.size(), 3u) << "one instance per row; the node itself is not drawn";
    const glm::mat4 node = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -1));
    // Row 1: T (2,0,0), R 90 degrees about Z, S 2. The vertex (1,0,0) goes to
    // scale (2,0,0), rotate (0,2,0), translate (2,2,0), node (2,2,-1).
    const glm::vec3 expected[3] = {{1, 0, -1}, {2, 2, -1}, {3, 0, -1}}; // rows 0, 1, 2
    for (int row = 0; row < 3; ++row) {
        const auto& inst = s.instances[std::size_t(row)];
        EXPECT_EQ(inst.row, row);
        EXPECT_EQ(inst.node_id, 0u);
        const glm::vec3 p = apply(inst.world, {1, 0, 0});
        EXPECT_NEAR(glm::distance(p, expected[row]), 0.0f, 1e-5f) << "row " << row;
        EXPECT_TRUE(inside(inst.world_bounds, p)) << "row " << row;
        EXPECT_EQ(inst.world, node * sherpa::scene::instance_transform(s, inst));
    }
    EXPECT_EQ(s.node_primitive_pairs(), 3u) << "counted once per row";
    // Posed (the default pose) like the renderer's pose pass and the CPU posing.
    const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(s, -1, 0.0);
    const auto bounds = sherpa::scene::instance_culling_bounds(s, pose);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_TRUE(inside(bounds[i], apply(s.instances[i].world, {1, 0, 0}))) << i;
    const sherpa::scene::PosedBounds posed = sherpa::scene::posed_scene_bounds(s, pose);
    EXPECT_NEAR(glm::distance(posed.exact.min, s.bounds.min), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(posed.exact.max, s.bounds.max), 0.0f, 1e-5f);
    const sherpa::scene::Scene frozen = sherpa::scene::freeze_pose(s, pose);
    ASSERT_EQ(frozen.instances.size(), 3u);
    EXPECT_NEAR(glm::distance(frozen.meshes[1].vertices[1].position, expected[1]), 0.0f, 1e-5f);
}

TEST(GpuInstancing, CountsThatDifferDrawTheSmallestWithAWarning) {
    const auto r = load("instancing_count_mismatch.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->instances.size(), 2u);
    EXPECT_TRUE(has_warning(*r.scene, "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes: "
                                      "counts differ (ROTATION 2, SCALE 3, TRANSLATION 3)"))
        << all_warnings(*r.scene);
}

TEST(GpuInstancing, NonFiniteAndZeroRotationRowsAreLeftOutWithAWarning) {
    const auto r = load("instancing_bad_rows.gltf");
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->instances.size(), 1u);
    EXPECT_EQ(r.scene->nodes[0].instancing->rows[0].file_row, 0u);
    EXPECT_TRUE(has_warning(*r.scene, "nodes[0].extensions.EXT_mesh_gpu_instancing: 2 of 3 rows "
                                      "have a non-finite translation, rotation or scale, or a "
                                      "zero rotation (first: row 1)"))
        << all_warnings(*r.scene);
    EXPECT_TRUE(sherpa::core::is_finite(r.scene->bounds.min) &&
                sherpa::core::is_finite(r.scene->bounds.max));
}

TEST(GpuInstancing, ACountItsBytesDoNotBackDrawsTheNodeOnce) {
    const auto r = load("instancing_huge_count.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_FALSE(r.scene->nodes[0].instancing);
    EXPECT_EQ(r.scene->instances.size(), 1u);
    EXPECT_TRUE(has_warning(*r.scene, "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes."
                                      "TRANSLATION"))
        << all_warnings(*r.scene);
    EXPECT_TRUE(has_warning(*r.scene, "the node is drawn once")) << all_warnings(*r.scene);
}

TEST(GpuInstancing, AComponentTypeTheExtensionDoesNotAllowIsNamedAndRead) {
    const auto r = load("instancing_ushort_translation.gltf");
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->instances.size(), 3u);
    EXPECT_EQ(r.scene->nodes[0].instancing->rows[2].translation, glm::vec3(4, 0, 0));
    EXPECT_TRUE(has_warning(*r.scene, "TRANSLATION: componentType 5123 is not one "
                                      "EXT_mesh_gpu_instancing allows for TRANSLATION (FLOAT)"))
        << all_warnings(*r.scene);
}

// An id tinygltf's int cannot hold (2^32 would read as accessor 0): the attribute is
// ignored by name and pointer, and the node is drawn once, as without the extension.
TEST(GpuInstancing, AnAccessorIdPast2To31IsIgnoredAndTheNodeDrawnOnce) {
    const auto r = load("instancing_id_2p32.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->instances.size(), 1u);
    EXPECT_FALSE(r.scene->nodes[0].instancing.has_value());
    bool named = false;
    for (const auto& m : r.scene->validation.messages)
        named |=
            m.code == "SHERPA_VALUE_IGNORED" &&
            m.pointer == "/nodes/0/extensions/EXT_mesh_gpu_instancing/attributes/TRANSLATION" &&
            m.severity == sherpa::scene::Severity::Warning &&
            m.message.find("4294967296 is not an accessor index") != std::string::npos;
    EXPECT_TRUE(named);
    EXPECT_TRUE(has_warning(*r.scene, "the node is drawn once")) << all_warnings(*r.scene);
}

TEST(GpuInstancing, ANodeWithoutAMeshIsNamed) {
    const auto r = load("instancing_no_mesh.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->instances.size(), 3u) << "node 0's rows";
    EXPECT_TRUE(has_warning(*r.scene, "nodes[1].extensions.EXT_mesh_gpu_instancing: the node has "
                                      "no mesh"))
        << all_warnings(*r.scene);
}

TEST(GpuInstancing, RowsPastTheInstanceLimitAreNotDrawn) {
    const auto r = load("instancing_over_limit.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->instances.size(), sherpa::scene::kMaxGpuInstanceRows);
    EXPECT_EQ(r.scene->nodes[0].instancing->file_rows, 1u << 20);
    EXPECT_EQ(r.scene->nodes[0].instancing->rows.size(), sherpa::scene::kMaxGpuInstanceRows / 2);
    EXPECT_TRUE(has_warning(*r.scene, "rows 524288..1048575 not drawn: the file's instanced rows "
                                      "x primitives reach the limit of 1048576 instances"))
        << all_warnings(*r.scene);
}

} // namespace
