// KHR_draco_mesh_compression beyond positions, normals and UVs, on files gltf-transform
// writes (the gltf_compress_corpus fixture): decoded attributes keep the component
// type their accessor declares, so a skinned file passes the skin checks with its
// joints identical to the uncompressed source's, weights within Draco's 12-bit
// generic quantization; morph targets (which Draco does not hold: gltf-transform
// keeps them uncompressed beside a sequential stream) pose like the source's;
// normalized colours, UVs and positions stay normalized integers. A primitive whose
// mode or missing indices contradict the stream's triangles is named and drawn with
// the stream's triangles.
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

std::string corpus(const std::string& file) {
    return (fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus" / file).string();
}

std::string all_warnings(const sherpa::scene::Scene& s) {
    std::string out;
    for (const auto& w : s.warnings) out += w + "\n";
    return out;
}

float max_extent(const sherpa::scene::Scene& s) {
    const glm::vec3 e = s.bounds.extent();
    return std::max({e.x, e.y, e.z});
}

// Every skinned vertex of the compressed file has a source vertex at the same place
// (14-bit positions over the extent) with the same four joints and weights within
// one 12-bit step, and the other way round (Draco's edgebreaker reorders vertices).
std::size_t unmatched_skin(const sherpa::scene::PrimitiveMotion& a,
                           const sherpa::scene::PrimitiveMotion& b, float position_tol,
                           float weight_tol) {
    std::size_t misses = 0;
    const std::uint32_t n = a.influences;
    for (std::size_t i = 0; i < a.base_positions.size(); ++i) {
        bool found = false;
        for (std::size_t j = 0; j < b.base_positions.size() && !found; ++j) {
            const glm::vec3 d = glm::abs(a.base_positions[i] - b.base_positions[j]);
            if (std::max({d.x, d.y, d.z}) > position_tol) continue;
            bool same = true;
            for (std::uint32_t k = 0; k < n && same; ++k)
                same =
                    a.weights[i * n + k] == 0.0f && b.weights[j * n + k] == 0.0f
                        ? std::abs(a.weights[i * n + k] - b.weights[j * n + k]) <= weight_tol
                        : a.joints[i * n + k] == b.joints[j * n + k] &&
                              std::abs(a.weights[i * n + k] - b.weights[j * n + k]) <= weight_tol;
            found = same;
        }
        misses += found ? 0 : 1;
    }
    return misses;
}

TEST(DracoAttributes, SkinnedFileKeepsItsJointsAsIntegers) {
    const sherpa::scene::LoadResult draco =
        sherpa::scene::load_scene(corpus("RiggedSimple.draco.glb"));
    ASSERT_TRUE(draco) << draco.error; // was: JOINTS_0 ... (componentType 5126)
    const sherpa::scene::LoadResult source =
        sherpa::scene::load_scene(test::gltf_asset("RiggedSimple"));
    ASSERT_TRUE(source) << source.error;
    ASSERT_EQ(draco.scene->motions.size(), source.scene->motions.size());
    ASSERT_FALSE(draco.scene->motions.empty());
    ASSERT_TRUE(draco.scene->primitives[0].compression);
    const float position_tol = max_extent(*source.scene) / float((1 << 14) - 1) * 1.01f;
    const float weight_tol = 1.5f / float((1 << 12) - 1);
    for (std::size_t m = 0; m < draco.scene->motions.size(); ++m) {
        const auto &a = draco.scene->motions[m], &b = source.scene->motions[m];
        ASSERT_TRUE(a.skinned());
        EXPECT_EQ(a.influences, b.influences);
        EXPECT_EQ(a.base_positions.size(), b.base_positions.size());
        EXPECT_EQ(unmatched_skin(a, b, position_tol, weight_tol), 0u) << "compressed vertices";
        EXPECT_EQ(unmatched_skin(b, a, position_tol, weight_tol), 0u) << "source vertices";
    }
    // Posed by its animation, every vertex lies on a source vertex's pose.
    ASSERT_FALSE(draco.scene->animations.empty());
    for (const double t : {0.3, 1.1, 2.9}) {
        const sherpa::scene::Pose pa = sherpa::scene::evaluate_pose(*draco.scene, 0, t),
                                  pb = sherpa::scene::evaluate_pose(*source.scene, 0, t);
        const sherpa::scene::PosedBounds a = sherpa::scene::posed_scene_bounds(*draco.scene, pa),
                                         b = sherpa::scene::posed_scene_bounds(*source.scene, pb);
        EXPECT_LE(glm::distance(a.exact.min, b.exact.min), 4 * position_tol) << t;
        EXPECT_LE(glm::distance(a.exact.max, b.exact.max), 4 * position_tol) << t;
    }
}

// Morph targets stay uncompressed; gltf-transform switches to sequential coding and
// writes them in the stream's point order (not necessarily the source's): every posed
// vertex lies on a posed source vertex, so the deltas follow their points.
class DracoMorph : public ::testing::TestWithParam<std::string> {};

TEST_P(DracoMorph, PosesLikeTheSource) {
    const std::string model = GetParam();
    const sherpa::scene::LoadResult draco = sherpa::scene::load_scene(corpus(model + ".draco.glb"));
    ASSERT_TRUE(draco) << draco.error;
    const sherpa::scene::LoadResult source = sherpa::scene::load_scene(test::gltf_asset(model));
    ASSERT_TRUE(source) << source.error;
    const sherpa::scene::Scene &a = *draco.scene, &b = *source.scene;
    bool said = false;
    for (const auto& p : a.primitives) {
        ASSERT_TRUE(p.compression);
        EXPECT_NE(p.compression->modes.find("sequential"), std::string::npos);
        if (p.morph_targets)
            said = said ||
                   p.compression->modes.find("morph targets uncompressed") != std::string::npos;
    }
    EXPECT_TRUE(said) << "info says the targets are not in the Draco stream";
    const float tol = max_extent(b) / float((1 << 14) - 1) * 1.01f;
    for (const double t : {0.0, 0.4, 1.3}) {
        const std::int32_t anim = b.animations.empty() ? -1 : 0;
        const sherpa::scene::Pose pa = sherpa::scene::evaluate_pose(a, anim, t),
                                  pb = sherpa::scene::evaluate_pose(b, anim, t);
        for (std::size_t p = 0; p < a.primitives.size(); ++p) {
            std::uint32_t node = 0;
            while (node < a.nodes.size() &&
                   a.nodes[node].mesh != std::int32_t(a.primitives[p].mesh))
                ++node;
            ASSERT_LT(node, a.nodes.size());
            const auto va = sherpa::scene::posed_positions(a, pa, node, a.primitives[p]);
            const auto vb = sherpa::scene::posed_positions(b, pb, node, b.primitives[p]);
            ASSERT_EQ(va.size(), vb.size());
            float worst = 0.0f; // each vertex to the nearest posed source vertex
            for (const glm::vec3& v : va) {
                float nearest = INFINITY;
                for (const glm::vec3& q : vb) nearest = std::min(nearest, glm::distance(v, q));
                worst = std::max(worst, nearest);
            }
            EXPECT_LE(worst, 2.0f * tol) << "time " << t << ", primitive " << p;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(GltfTransform, DracoMorph,
                         ::testing::Values("SimpleMorph", "AnimatedMorphSphere"));

// gltf-transform quantize then draco: the integer attributes come back as the
// accessors declare them (unsigned byte colours, unsigned short UVs, short positions).
TEST(DracoAttributes, NormalizedIntegersStayNormalizedIntegers) {
    const sherpa::scene::LoadResult draco =
        sherpa::scene::load_scene(corpus("BoxVertexColors.quantized.draco.glb"));
    ASSERT_TRUE(draco) << draco.error;
    const sherpa::scene::LoadResult source =
        sherpa::scene::load_scene(test::gltf_asset("BoxVertexColors"));
    ASSERT_TRUE(source) << source.error;
    EXPECT_TRUE(draco.scene->range_violations.empty()) << all_warnings(*draco.scene);
    const sherpa::scene::Mesh& m = draco.scene->meshes.at(0);
    ASSERT_TRUE(m.sources[std::size_t(sherpa::scene::VertexAttribute::TexCoord0)]);
    const auto& uv = *m.sources[std::size_t(sherpa::scene::VertexAttribute::TexCoord0)];
    EXPECT_EQ(uv.component_type, 5123);
    EXPECT_TRUE(uv.normalized);
    const auto& pos = *m.sources[std::size_t(sherpa::scene::VertexAttribute::Position)];
    EXPECT_EQ(pos.component_type, 5122);
    EXPECT_TRUE(pos.normalized);
    ASSERT_TRUE(m.sources[std::size_t(sherpa::scene::VertexAttribute::Color0)]);
    EXPECT_EQ(m.sources[std::size_t(sherpa::scene::VertexAttribute::Color0)]->component_type, 5121);
    // Colours: every drawn colour is a source colour within one 8-bit step, at a
    // vertex within quantization of a source vertex (world space: quantize moves the
    // dequantization into the node transform).
    ASSERT_FALSE(m.colors.empty());
    const auto& src = source.scene->meshes.at(0);
    const glm::mat4 wa = draco.scene->instances.at(0).world,
                    wb = source.scene->instances.at(0).world;
    const float tol = max_extent(*source.scene) / float((1 << 14) - 1) * 1.5f;
    std::size_t misses = 0;
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const glm::vec3 p = glm::vec3(wa * glm::vec4(m.vertices[i].position, 1.0f));
        bool found = false;
        for (std::size_t j = 0; j < src.vertices.size() && !found; ++j) {
            const glm::vec3 q = glm::vec3(wb * glm::vec4(src.vertices[j].position, 1.0f));
            const glm::vec4 dc = glm::abs(m.colors[i] - src.colors[j]);
            found = glm::distance(p, q) <= tol &&
                    std::max({dc.x, dc.y, dc.z, dc.w}) <= 1.01f / 255.0f &&
                    glm::distance(m.vertices[i].uv0, src.vertices[j].uv0) <= 1.5f / 4095.0f;
        }
        misses += found ? 0 : 1;
    }
    EXPECT_EQ(misses, 0u) << "of " << m.vertices.size() << " vertices";
}

// A copy of gltf-transform's Duck.draco.gltf (and its .bin), edited.
std::string edited_duck(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    const fs::path dir =
        fs::temp_directory_path() / ("sherpa_draco_mode_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    nlohmann::json doc = test::read_json(corpus("Duck.draco.gltf"));
    for (const auto& b : doc["buffers"])
        fs::copy_file(fs::path(corpus(b["uri"].get<std::string>())),
                      dir / b["uri"].get<std::string>(), fs::copy_options::overwrite_existing);
    edit(doc);
    const fs::path out = dir / name;
    std::ofstream(out) << doc.dump();
    return out.string();
}

std::uint64_t triangles(const sherpa::scene::Scene& s) {
    std::uint64_t n = 0;
    for (const auto& m : s.meshes) n += m.triangle_count();
    return n;
}

TEST(DracoModeAndIndices, AStripModeOverTheStreamsTriangleListIsNamed) {
    const sherpa::scene::LoadResult plain = sherpa::scene::load_scene(corpus("Duck.draco.gltf"));
    ASSERT_TRUE(plain) << plain.error;
    const std::string path = edited_duck(
        "strip.gltf", [](nlohmann::json& doc) { doc["meshes"][0]["primitives"][0]["mode"] = 5; });
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    EXPECT_NE(all_warnings(*r.scene).find("meshes[0].primitives[0].mode: 5 (TRIANGLE_STRIP) "
                                          "contradicts the Draco stream, which holds 4212 "
                                          "triangles as a list; drawn as TRIANGLES (4)"),
              std::string::npos)
        << all_warnings(*r.scene);
    EXPECT_EQ(triangles(*r.scene), triangles(*plain.scene)) << "not 12,634 strip triangles";
    EXPECT_EQ(r.scene->meshes[0].indices, plain.scene->meshes[0].indices);
}

TEST(DracoModeAndIndices, MissingIndicesOverOutOfOrderFacesAreNamed) {
    const sherpa::scene::LoadResult plain = sherpa::scene::load_scene(corpus("Duck.draco.gltf"));
    ASSERT_TRUE(plain) << plain.error;
    const std::string path = edited_duck("no_indices.gltf", [](nlohmann::json& doc) {
        doc["meshes"][0]["primitives"][0].erase("indices");
    });
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    const std::string w = all_warnings(*r.scene);
    EXPECT_NE(w.find("meshes[0].primitives[0].indices: missing, but the Draco stream's 4212 "
                     "triangles index its 2399 points out of order; drawn with the stream's "
                     "triangles"),
              std::string::npos)
        << w;
    EXPECT_EQ(w.find("trailing indices ignored"), std::string::npos) << w;
    EXPECT_EQ(triangles(*r.scene), triangles(*plain.scene));
    EXPECT_EQ(r.scene->meshes[0].indices, plain.scene->meshes[0].indices);
}

} // namespace
