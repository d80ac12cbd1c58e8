// EXT_mesh_gpu_instancing as the ecosystem writes it (the gltf_compress_corpus
// fixture): 2CylinderEngine instanced by gltfpack -mi (required; quantized
// rotations) and by gltf-transform instance (float rows). The reference is the
// uncompressed source: the same triangles in the same place, the same picture from
// the rasterizer and from the ray tracer (whose TLAS holds one instance per row),
// under the validation layer; `info` counts the rows.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <filesystem>
#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

std::string corpus(const std::string& file) {
    return (fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus" / file).string();
}

struct Totals {
    std::uint64_t triangles = 0, row_instances = 0, rows = 0, file_rows = 0, nodes = 0;
};

Totals totals(const sherpa::scene::Scene& s) {
    Totals t;
    for (const auto& inst : s.instances) {
        t.triangles += s.meshes[inst.mesh_id].triangle_count();
        t.row_instances += inst.row >= 0 ? 1 : 0;
    }
    for (const auto& n : s.nodes)
        if (n.instancing) {
            ++t.nodes;
            t.rows += n.instancing->rows.size();
            t.file_rows += n.instancing->file_rows;
        }
    return t;
}

class InstancedFile : public ::testing::TestWithParam<std::string> {};

TEST_P(InstancedFile, DrawsTheSourcesTrianglesInPlace) {
    const sherpa::scene::LoadResult inst = sherpa::scene::load_scene(corpus(GetParam()));
    ASSERT_TRUE(inst) << inst.error;
    const sherpa::scene::LoadResult source =
        sherpa::scene::load_scene(test::gltf_asset("2CylinderEngine"));
    ASSERT_TRUE(source) << source.error;
    for (const auto& w : inst.scene->warnings)
        EXPECT_EQ(w.find("EXT_mesh_gpu_instancing"), std::string::npos) << w;
    const Totals a = totals(*inst.scene), b = totals(*source.scene);
    ASSERT_GT(a.nodes, 0u) << "the tool instanced nothing: the test checks nothing";
    EXPECT_EQ(a.rows, a.file_rows) << "every row drawn";
    EXPECT_GT(a.row_instances, a.nodes) << "rows became instances";
    // gltfpack welds vertices and drops the triangles that then collapse (as in the
    // compressed-geometry test); gltf-transform keeps every triangle.
    if (GetParam().find("gt_instance") != std::string::npos)
        EXPECT_EQ(a.triangles, b.triangles);
    else
        EXPECT_GE(a.triangles, b.triangles * 8 / 10);
    EXPECT_LE(a.triangles, b.triangles);
    // World bounds within gltfpack's 14-bit position step of the same tool's file
    // without instancing (gltfpack drops geometry that changes the source's bounds).
    const sherpa::scene::LoadResult plain =
        GetParam().find("gt_instance") != std::string::npos
            ? sherpa::scene::load_scene(test::gltf_asset("2CylinderEngine"))
            : sherpa::scene::load_scene(corpus("2CylinderEngine.meshopt.glb"));
    ASSERT_TRUE(plain) << plain.error;
    const glm::vec3 e = plain.scene->bounds.extent();
    const float step = std::max({e.x, e.y, e.z}) / float((1 << 14) - 1);
    EXPECT_LE(glm::distance(inst.scene->bounds.min, plain.scene->bounds.min), 2 * step);
    EXPECT_LE(glm::distance(inst.scene->bounds.max, plain.scene->bounds.max), 2 * step);
}

TEST_P(InstancedFile, InfoCountsTheRows) {
    const sherpa::scene::LoadResult inst = sherpa::scene::load_scene(corpus(GetParam()));
    ASSERT_TRUE(inst) << inst.error;
    const Totals t = totals(*inst.scene);
    const test::CliRun r = test::run_cli("info '" + corpus(GetParam()) + "' --json", "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out).at("gpu_instancing");
    EXPECT_EQ(j.at("nodes").size(), t.nodes);
    EXPECT_EQ(j.at("file_rows").get<std::uint64_t>(), t.file_rows);
    EXPECT_EQ(j.at("drawn_rows").get<std::uint64_t>(), t.rows);
    EXPECT_EQ(j.at("instances").get<std::uint64_t>(), t.row_instances);
    EXPECT_GE(j.at("nodes").at(0).at("translation").get<int>(), 0);
    const test::CliRun text = test::run_cli("info '" + corpus(GetParam()) + "'");
    ASSERT_EQ(text.exit_code, 0) << text.out;
    EXPECT_NE(text.out.find("gpu instancing: " + std::to_string(t.nodes) + " node(s), " +
                            std::to_string(t.rows) + " rows drawn of " +
                            std::to_string(t.file_rows) + " -> " + std::to_string(t.row_instances) +
                            " instances"),
              std::string::npos)
        << text.out;
}

// The source and the instanced file rendered from the same camera, raster against
// raster (lit) and rays against rays (normals: the ray tracer does not shade every view):
// only quantization noise differs.
TEST_P(InstancedFile, RendersLikeTheSource) {
    const fs::path png =
        fs::temp_directory_path() / ("sherpa_instanced_" + std::to_string(::getpid()) + ".png");
    for (const std::string renderer : {"raster", "rt"}) {
        SCOPED_TRACE(renderer);
        const test::CliRun r = test::run_cli(
            "render '" + test::gltf_asset("2CylinderEngine") + "' -o '" + png.string() +
                "' --width 160 --height 120 --validation --no-cache --no-shadows --rt on"
                " --renderer " +
                renderer + (renderer == "rt" ? " --view normal" : "") +
                " --compare difference --compare-renderer " + renderer + " --compare-with '" +
                corpus(GetParam()) + "' --threshold 16 --json",
            "2>/dev/null");
        ASSERT_EQ(r.exit_code, 0) << r.out;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_LT(j.at("over_threshold_percent").get<double>(), 1.0) << j.dump();
        EXPECT_GT(j.at("psnr_db").is_null() ? 99.0 : j.at("psnr_db").get<double>(), 35.0)
            << j.dump();
    }
    fs::remove(png);
}

// Every row is an instance of the TLAS.
TEST_P(InstancedFile, TheTlasHoldsEveryRow) {
    const sherpa::scene::LoadResult inst = sherpa::scene::load_scene(corpus(GetParam()));
    ASSERT_TRUE(inst) << inst.error;
    const test::CliRun r =
        test::run_cli("rt '" + corpus(GetParam()) + "' --json --validation", "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto tlas = nlohmann::json::parse(r.out).at("tlas");
    const Totals t = totals(*inst.scene);
    EXPECT_GE(tlas.at("node_mesh_pairs").get<std::uint64_t>(), t.rows);
    EXPECT_EQ(tlas.at("instances").get<std::uint64_t>() +
                  tlas.at("deduplicated").get<std::uint64_t>(),
              tlas.at("node_mesh_pairs").get<std::uint64_t>());
}

INSTANTIATE_TEST_SUITE_P(NpmTools, InstancedFile,
                         ::testing::Values("2CylinderEngine.instanced.glb",
                                           "2CylinderEngine.gt_instance.glb"),
                         [](const auto& param_info) {
                             std::string n = param_info.param;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

} // namespace
