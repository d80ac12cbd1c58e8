// sherpa-cli rt: acceleration structures of real assets and hostile scenes under the
// validation layer (any message fails the run), and `--rt off` on render and rt.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_json.h" // info_json: the importer's counts, independent of the AS code
#include "cli_run.h"
#include "test_support.h"

#include <sherpa/texture/image.h>

namespace sherpa::test {
namespace {

using nlohmann::json;

json rt_json(const std::string& scene, const std::string& extra = "") {
    const CliRun r = run_cli("rt '" + scene + "' --json --validation " + extra, "2>/dev/null");
    EXPECT_EQ(r.exit_code, 0) << scene << "\n" << r.out;
    return r.exit_code == 0 ? json::parse(r.out) : json();
}

void expect_consistent(const json& j, const std::string& scene) {
    SCOPED_TRACE(scene);
    std::uint64_t triangles = 0, geometries = 0, built = 0, compacted = 0;
    std::uint32_t next_record = 0;
    for (const json& b : j["blas"]) {
        EXPECT_GT(b["geometries"].get<int>(), 0);
        EXPECT_GT(b["triangles"].get<std::uint64_t>(), 0u);
        EXPECT_LE(b["opaque_geometries"].get<int>(), b["geometries"].get<int>());
        EXPECT_TRUE(b["culls_back_faces"].is_boolean());
        EXPECT_EQ(b["first_geometry"].get<std::uint32_t>(), next_record); // one array, in order
        next_record += b["geometries"].get<std::uint32_t>();
        EXPECT_GT(b["scratch_bytes"].get<std::uint64_t>(), 0u);
        EXPECT_GT(b["build_bytes"].get<std::uint64_t>(), 0u);
        EXPECT_LE(b["compacted_bytes"].get<std::uint64_t>(), b["build_bytes"].get<std::uint64_t>());
        EXPECT_GE(b["build_ms"].get<double>(), 0.0);
        triangles += b["triangles"].get<std::uint64_t>();
        geometries += b["geometries"].get<std::uint64_t>();
        built += b["build_bytes"].get<std::uint64_t>();
        compacted += b["compacted_bytes"].get<std::uint64_t>();
    }
    const json& t = j["totals"];
    EXPECT_EQ(t["triangles"].get<std::uint64_t>(), triangles);
    EXPECT_EQ(t["geometry_records"].get<std::uint64_t>(), geometries);
    EXPECT_EQ(t["geometry_record_bytes"].get<std::uint64_t>(), geometries * 64);
    EXPECT_EQ(t["blas_build_bytes"].get<std::uint64_t>(), built);
    EXPECT_EQ(t["blas_compacted_bytes"].get<std::uint64_t>(), compacted);
    const json& tl = j["tlas"];
    EXPECT_EQ(tl["node_mesh_pairs"].get<std::uint64_t>(),
              tl["instances"].get<std::uint64_t>() + tl["deduplicated"].get<std::uint64_t>() +
                  tl["hidden"].get<std::uint64_t>() + tl["non_finite"].get<std::uint64_t>());
    EXPECT_EQ(tl["instance_buffer_bytes"].get<std::uint64_t>(),
              tl["instances"].get<std::uint64_t>() * 64);
}

TEST(CliRt, SampleModelsBuildValidationClean) {
    for (const char* model : {"Box", "DamagedHelmet", "2CylinderEngine", "AlphaBlendModeTest",
                              "TwoSidedPlane", "TriangleWithoutIndices", "SimpleMeshes",
                              "NormalTangentMirrorTest", "OrientationTest", "VertexColorTest"}) {
        const std::string path = gltf_asset(model);
        const json j = rt_json(path);
        if (j.is_null()) continue;
        expect_consistent(j, model);
        // Every triangle the importer made is in a BLAS (these models instance every mesh).
        EXPECT_EQ(j["totals"]["triangles"].get<std::uint64_t>(),
                  info_json(path)["triangles"].get<std::uint64_t>())
            << model;
        EXPECT_GT(j["tlas"]["instances"].get<std::uint64_t>(), 0u) << model;
    }
}

TEST(CliRt, MaskedAndBlendedGeometriesAreNotOpaque) {
    const json j = rt_json(gltf_asset("AlphaBlendModeTest"));
    ASSERT_FALSE(j.is_null());
    std::uint64_t opaque = 0, all = 0;
    for (const json& b : j["blas"]) {
        opaque += b["opaque_geometries"].get<std::uint64_t>();
        all += b["geometries"].get<std::uint64_t>();
    }
    // The model has opaque, masked and blended materials.
    EXPECT_GT(opaque, 0u);
    EXPECT_LT(opaque, all);
}

TEST(CliRt, HundredThousandInstanceGrid) {
    const std::string grid = "builtin:grid?n=100000";
    const json j = rt_json(grid);
    ASSERT_FALSE(j.is_null());
    expect_consistent(j, grid);
    EXPECT_EQ(j["tlas"]["node_mesh_pairs"].get<std::uint64_t>(),
              info_json(grid)["drawable_instances"].get<std::uint64_t>());
    EXPECT_EQ(j["tlas"]["instances"].get<std::uint64_t>(), 100000u);
}

TEST(CliRt, ScratchBudgetSplitsBuildsIntoBatches) {
    const std::string engine = gltf_asset("2CylinderEngine");
    const json one = rt_json(engine);
    // A budget smaller than any build: every BLAS is a batch of its own, and the
    // scratch buffer is the largest single build's.
    const json tight = rt_json(engine, "--scratch-budget 1");
    ASSERT_FALSE(one.is_null());
    ASSERT_FALSE(tight.is_null());
    EXPECT_EQ(one["totals"]["batches"].get<std::size_t>(), 1u);
    EXPECT_EQ(tight["totals"]["batches"].get<std::size_t>(), tight["blas"].size());
    std::uint64_t largest = 0;
    for (const json& b : tight["blas"])
        largest = std::max(largest, b["scratch_bytes"].get<std::uint64_t>());
    EXPECT_GE(tight["totals"]["scratch_buffer_bytes"].get<std::uint64_t>(), largest);
    EXPECT_LT(tight["totals"]["scratch_buffer_bytes"].get<std::uint64_t>(), largest + 256);
    EXPECT_EQ(tight["totals"]["triangles"], one["totals"]["triangles"]);
}

TEST(CliRt, HostileFilesFailOrBuildCleanly) {
    // Empty, non-finite and malformed geometry: a clear load error naming the file
    // or a validation-clean build, never a crash. (Degenerate triangles, NaN
    // transforms and empty meshes built by hand: acceleration_structures_test.cpp.)
    for (const char* file :
         {"empty.gltf", "empty_primitive.gltf", "nan_position.gltf", "inf_position.gltf",
          "points.gltf", "nan_normals.gltf", "fan.gltf", "strip.gltf", "no_material.gltf",
          "index_beyond_vertices.gltf", "huge_count.gltf"}) {
        const std::string path = (data_dir() / file).string();
        const CliRun r = run_cli("rt '" + path + "' --json --validation", "2>&1");
        EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << file << "\n" << r.out;
        if (r.exit_code == 1) {
            EXPECT_NE(r.out.find("error: "), std::string::npos) << r.out;
        } else {
            EXPECT_EQ(r.out.find("validation"), std::string::npos) << r.out;
        }
    }
}

TEST(CliRt, RtOffAllocatesNothingAndSaysSo) {
    const CliRun off = run_cli("rt builtin:default --rt off", "2>&1");
    EXPECT_EQ(off.exit_code, 1);
    EXPECT_NE(off.out.find("ray tracing is off"), std::string::npos) << off.out;
    EXPECT_EQ(run_cli("rt builtin:default --rt maybe").exit_code, 2);
    EXPECT_EQ(run_cli("rt").exit_code, 2);
}

TEST(CliRt, RenderReportShowsBuildInputUsageOnlyWithRt) {
    const std::string dir = ::testing::TempDir();
    auto report = [&](const std::string& rt) {
        const std::string png = dir + "/rt_" + rt + ".png", js = dir + "/rt_" + rt + ".json";
        const CliRun r = run_cli("render builtin:default -o " + png +
                                 " --width 32 --height 32 --no-cache --validation --rt " + rt +
                                 " --report " + js);
        EXPECT_EQ(r.exit_code, 0) << r.out;
        return read_json(js);
    };
    const json on = report("on"), off = report("off");
    EXPECT_FALSE(off["device"]["ray_tracing_enabled"].get<bool>());
    EXPECT_FALSE(off["geometry_buffers"]["acceleration_structure_input"].get<bool>());
    EXPECT_EQ(off["gpu_memory_bytes"]["total"], on["gpu_memory_bytes"]["total"]);
    if (on["device"]["ray_tracing"].get<bool>()) {
        EXPECT_TRUE(on["device"]["ray_tracing_enabled"].get<bool>());
        EXPECT_TRUE(on["geometry_buffers"]["acceleration_structure_input"].get<bool>());
    }
}

// render --renderer rt: the helmet's normal view through rays, validation clean, close
// to the rasterizer's (the exactness check itself is tests/gpu/rt_exactness_test.cpp);
// views the ray tracer has no formula for, overlays and --rt off are refused.
TEST(CliRt, RenderRendererRtDrawsSurfaceViewsAndRefusesTheRest) {
    const std::string dir = ::testing::TempDir();
    const std::string helmet = "'" + gltf_asset("DamagedHelmet") + "'";
    const std::string common = " --width 64 --height 48 --view normal --texture-lod 0 --validation"
                               " --cache-dir '" SHERPA_TEST_TEXTURE_CACHE "'";
    std::vector<std::uint8_t> images[2];
    for (int i = 0; i < 2; ++i) {
        const std::string png = dir + "/renderer_" + std::to_string(i) + ".png";
        const CliRun r = run_cli("render " + helmet + " -o " + png + common + " --renderer " +
                                     (i ? "rt" : "raster"),
                                 "2>&1");
        ASSERT_EQ(r.exit_code, 0) << r.out;
        std::uint32_t w = 0, h = 0;
        std::string error;
        ASSERT_TRUE(tex::read_png_rgba8(png, w, h, images[i], error)) << error;
        EXPECT_EQ(w, 64u);
    }
    std::size_t close = 0;
    for (std::size_t p = 0; p + 3 < images[0].size(); p += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(images[0][p + c] - images[1][p + c]));
        close += d <= 2;
    }
    EXPECT_GE(close, images[0].size() / 4 * 98 / 100); // silhouettes included here
    const std::string out = " -o " + dir + "/refused.png";
    for (const std::string bad : {" --view joint-influence", " --view uv0-checker",
                                  " --overlay aabb", " --rt off", " --texture-lod -1"}) {
        const CliRun r =
            run_cli("render " + helmet + out + " --renderer rt --width 8 --height 8" + bad, "2>&1");
        EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out;
    }
    EXPECT_EQ(run_cli("render builtin:default -o x.png --renderer vulkan").exit_code, 2);
}

// Meshes that skin or morph: a posed BLAS per instance over posed copies of the moving
// vertices (bytes reported), no static BLAS for a mesh only instanced posed; static
// scenes carry none of it. `render --renderer rt --animation --time` draws a posed
// frame validation-clean (its exactness: RtExactness.PosedFramesAgree).
TEST(CliRt, PosedMeshesGetPosedStreamsAndBlasOnlyWhereTheyMove) {
    const json rigged = rt_json(gltf_asset("RiggedSimple"));
    ASSERT_FALSE(rigged.is_null());
    const json& p = rigged["posed"];
    EXPECT_EQ(p["blas"].get<int>(), 1);
    EXPECT_EQ(p["world_space"].get<int>(), 1); // skinned
    EXPECT_EQ(p["update"], "refit");
    // Positions and normals (12 B each) of its vertices, after a 64-byte zero record.
    EXPECT_GE(p["stream_bytes"].get<std::uint64_t>(), 64 + 24 * p["vertices"].get<std::uint64_t>());
    EXPECT_GT(p["blas_bytes"].get<std::uint64_t>(), 0u);
    EXPECT_FALSE(rigged["blas"][0]["built"].get<bool>()); // its only instance is posed
    EXPECT_EQ(rigged["totals"]["blas_build_bytes"].get<std::uint64_t>(), 0u);
    const json morph = rt_json(gltf_asset("AnimatedMorphSphere"));
    ASSERT_FALSE(morph.is_null());
    EXPECT_EQ(morph["posed"]["blas"].get<int>(), 1);
    EXPECT_EQ(morph["posed"]["world_space"].get<int>(), 0); // morphed in the mesh's space
    for (const char* still : {"Box", "BoxAnimated"}) {      // BoxAnimated moves nodes only
        const json j = rt_json(gltf_asset(still));
        ASSERT_FALSE(j.is_null());
        EXPECT_EQ(j["posed"]["blas"].get<int>(), 0) << still;
        EXPECT_EQ(j["posed"]["stream_bytes"].get<std::uint64_t>(), 0u) << still;
        EXPECT_EQ(j["posed"]["blas_bytes"].get<std::uint64_t>(), 0u) << still;
    }
    const std::string png = ::testing::TempDir() + "/posed_rt.png";
    const CliRun r = run_cli("render '" + gltf_asset("RiggedSimple") + "' -o " + png +
                                 " --renderer rt --view normal --width 32 --height 24"
                                 " --animation 0 --time 0.5 --validation",
                             "2>&1");
    EXPECT_EQ(r.exit_code, 0) << r.out;
}

// The lighting views and their options: drawn validation-clean by the renderer that
// can; rays-only views and out-of-range values are usage errors.
TEST(CliRt, RenderShadowAndAoOptions) {
    const std::string dir = ::testing::TempDir();
    const std::string duck = "'" + gltf_asset("Duck") + "' --width 32 --height 24 --validation";
    for (const std::string ok :
         {" --view shadow --cascades 1 --shadow-resolution 512 --pcf-taps 16",
          " --view shadow --renderer rt --shadow-rays 4 --sun-angular-radius 0.05",
          " --view ao --renderer rt --ao-rays 4 --ao-radius 0.5",
          " --view shadow-error --renderer rt --cascades 2 --pcf-taps 4"}) {
        const CliRun r = run_cli("render " + duck + " -o " + dir + "/lighting.png" + ok, "2>&1");
        EXPECT_EQ(r.exit_code, 0) << ok << "\n" << r.out;
        if (ok.find("shadow-error") != std::string::npos) {
            EXPECT_NE(r.out.find("% of "), std::string::npos) << "the pixel classes counted";
        }
    }
    for (const std::string bad :
         {" --view ao", " --view shadow-error", " --pcf-taps 3", " --cascades 0", " --cascades 4",
          " --shadow-rays 0", " --sun-angular-radius -1", " --ao-radius nan",
          " --shadow-resolution 10"}) {
        const CliRun r = run_cli("render " + duck + " -o " + dir + "/bad.png" + bad, "2>&1");
        EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out;
    }
}

} // namespace
} // namespace sherpa::test
