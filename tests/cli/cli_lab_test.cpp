// sherpa-cli lab and compare: the JSON the Lab's families and the file comparison
// give, the CSV and SVG, and bad usage.
#include "cli/cli_run.h"
#include "test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using sherpa::test::run_cli;

nlohmann::json lab_json(const std::string& args) {
    const auto r = run_cli("lab " + args + " --json", "2>/dev/null");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return nlohmann::json::parse(r.out, nullptr, false);
}

TEST(CliLab, TangentsOnDamagedHelmetMatchTheDocumentedAccuracy) {
    const auto j =
        lab_json("'" + sherpa::test::gltf_asset("DamagedHelmet") + "' --family tangents");
    ASSERT_EQ(j.at("methods").size(), 3u);
    const auto& lengyel = j["methods"][2];
    EXPECT_EQ(lengyel.at("name"), "lengyel");
    // docs/tangents/methods.csv: 0.456144 mean, 44.0339 max degrees against exact.
    EXPECT_NEAR(lengyel["errors"]["angle_mean_deg"].get<double>(), 0.456144, 1e-5);
    EXPECT_NEAR(lengyel["errors"]["angle_max_deg"].get<double>(), 44.0339, 1e-3);
    EXPECT_EQ(j["methods"][0]["errors"]["angle_max_deg"].get<double>(), 0.0);
    // 24 corners with degenerate uvs on the helmet: a failure by cause, with where.
    EXPECT_EQ(lengyel["failures_by_cause"]["degenerate_uv"].get<int>(), 24);
    EXPECT_NE(lengyel["failures"][0]["where"].get<std::string>().find("mesh 0 primitive 0"),
              std::string::npos);
    EXPECT_EQ(j["time_unit"], "ms/Mtri");
    EXPECT_TRUE(lengyel["pareto"].get<bool>()) << "fastest";
}

TEST(CliLab, CullingOnAGridHasNoFalseNegatives) {
    const auto j = lab_json("'builtin:grid?n=400' --family culling --cameras 8 --no-gpu");
    ASSERT_EQ(j.at("methods").size(), 4u);
    for (int m = 0; m < 3; ++m) {
        EXPECT_EQ(j["methods"][m]["errors"]["false_negatives"].get<int>(), 0);
        EXPECT_GT(j["methods"][m]["time"].get<double>(), 0.0);
    }
    EXPECT_EQ(j["methods"][2]["errors"]["false_positives"].get<int>(), 0) << "exact";
    EXPECT_GE(j["methods"][0]["errors"]["false_positives"].get<int>(),
              j["methods"][1]["errors"]["false_positives"].get<int>())
        << "sphere keeps at least what p-vertex keeps";
    EXPECT_FALSE(j["methods"][3]["ran"].get<bool>());
}

TEST(CliLab, MeshCompressionJsonShape) {
    const auto j = lab_json("'" + sherpa::test::gltf_asset("Duck") + "' --family mesh-compression");
    EXPECT_EQ(j.at("family"), "mesh-compression");
    EXPECT_EQ(j.at("chart_error"), "position_rms");
    EXPECT_EQ(j.at("chart_x"), "bytes");
    EXPECT_EQ(j.at("time_unit"), "ms/Mvert");
    ASSERT_EQ(j.at("methods").size(), 16u);
    std::set<std::string> groups;
    for (const auto& m : j["methods"]) {
        SCOPED_TRACE(m.dump());
        groups.insert(m.at("group").get<std::string>());
        EXPECT_TRUE(m.at("ran").get<bool>());
        EXPECT_GT(m.at("time").get<double>(), 0.0);
        for (const char* e :
             {"position_rms", "position_max", "position_step", "bytes", "vertex_bytes",
              "index_bytes", "bytes_per_vertex", "normal_mean_deg", "normal_max_deg", "uv_rms",
              "uv_max", "uv_max_texels", "uv_rms_texels"})
            EXPECT_TRUE(m["errors"].contains(e)) << e;
        EXPECT_TRUE(m.at("failures").empty());
    }
    EXPECT_EQ(groups, (std::set<std::string>{"KHR_mesh_quantization", "meshopt codec"}));
    const auto& reference = j["methods"][0];
    EXPECT_EQ(reference["name"], "float");
    EXPECT_EQ(reference["errors"]["position_max"].get<double>(), 0.0);
    EXPECT_EQ(reference["errors"]["bytes_per_vertex"].get<double>(), 32.0) << "12 + 12 + 8";
    EXPECT_TRUE(reference["pareto"].get<bool>()) << "exact";
    EXPECT_TRUE(j["methods"][1]["pareto"].get<bool>()) << "fewest bytes of its group";
    // DuckCM.png is 512 x 512 (read from its header): uv error in its texels.
    for (const auto& m : j["methods"])
        EXPECT_NEAR(m["errors"]["uv_max_texels"].get<double>(),
                    m["errors"]["uv_max"].get<double>() * 512, 1e-6);
    // An empty primitive: nothing to quantize, said per method.
    const auto e = lab_json("'" + std::string(SHERPA_TEST_DATA_DIR) +
                            "/empty_primitive.gltf' --family mesh-compression");
    ASSERT_EQ(e.at("methods").size(), 16u);
    for (const auto& m : e["methods"]) {
        EXPECT_FALSE(m["ran"].get<bool>());
        EXPECT_EQ(m["note"], "no mesh primitive with vertices");
    }
}

// The shadows family's JSON: every cascade setting (3 resolutions x 3 cascade counts x 3
// PCF tap counts) with the chart error and its false-shadow / false-light split.
TEST(CliLab, ShadowsJsonShape) {
    const auto j = lab_json("'" + sherpa::test::gltf_asset("Box") +
                            "' --family shadows --cameras 1 --repeat 1");
    EXPECT_EQ(j.at("family"), "shadows");
    EXPECT_EQ(j.at("chart_error"), "lit_pixels_wrong_percent");
    EXPECT_EQ(j.at("time_unit"), "ms/frame");
    EXPECT_NE(j.at("reference").get<std::string>().find("ray-traced"), std::string::npos);
    ASSERT_EQ(j.at("methods").size(), 27u);
    EXPECT_EQ(j["methods"][0]["name"], "1024x1 pcf1");
    for (const auto& m : j["methods"]) {
        if (!m.at("ran").get<bool>()) {
            EXPECT_NE(m.at("note").get<std::string>().find("ray trace"), std::string::npos);
            continue;
        }
        for (const char* e : {"lit_pixels_wrong_percent", "false_shadow_percent",
                              "false_light_percent", "wrong_pixels", "lit_pixels"})
            EXPECT_TRUE(m.at("errors").contains(e)) << m["name"] << " " << e;
        EXPECT_GE(m.at("time").get<double>(), 0.0);
    }
}

// The shadows family's frames are lit as render lights its frame: the environment
// options are render's (a bad file is the same warning and fallback), a bad value is a
// usage error.
TEST(CliLab, ShadowsTakeTheEnvironmentOptions) {
    const std::string missing = "/no/such/environment.exr";
    const auto r = run_cli("lab '" + sherpa::test::gltf_asset("Box") +
                               "' --family shadows --cameras 1 --repeat 1 --json --environment " +
                               missing + " --tone-map agx --background 0,0,0",
                           "2>&1 >/dev/null");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("warning: " + missing), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("using the built-in room environment instead"), std::string::npos)
        << r.out;
    EXPECT_EQ(run_cli("lab builtin:default --family shadows --tone-map nope").exit_code, 2);
    // compare --image: both sides lit alike, by the same options.
    const std::string box = sherpa::test::gltf_asset("Box");
    const fs::path png =
        fs::temp_directory_path() / ("sherpa_compare_env_" + std::to_string(::getpid()) + ".png");
    const auto c = run_cli("compare '" + box + "' '" + box + "' --image '" + png.string() +
                               "' --environment " + missing,
                           "2>&1");
    EXPECT_EQ(c.exit_code, 0) << c.out;
    EXPECT_NE(c.out.find("warning: " + missing), std::string::npos) << c.out;
    EXPECT_NE(c.out.find("PSNR inf dB"), std::string::npos) << c.out;
    fs::remove(png);
}

// The lighting family on Box at 32x24 against 8 samples, lit by a small HDR (its
// prefilters are quick): the JSON's shape, the chart, and what the box cannot show.
TEST(CliLab, LightingJsonShapeAndChart) {
    const fs::path svg =
        fs::temp_directory_path() / ("sherpa_lab_lighting_" + std::to_string(::getpid()) + ".svg");
    ::setenv("SHERPA_VALIDATION", "1", 1); // each message a failure of its method
    const auto r = run_cli("lab '" + sherpa::test::gltf_asset("Box") +
                               "' --family lighting --width 32 --height 24 --reference-spp 8 "
                               "--repeat 1 --json --chart '" +
                               svg.string() + "' --environment '" + SHERPA_TEST_DATA_DIR +
                               "/cycles_oracle/sky.hdr'",
                           "2>/dev/null");
    ::unsetenv("SHERPA_VALIDATION");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << r.out;
    EXPECT_EQ(j.at("family"), "lighting");
    EXPECT_EQ(j.at("chart_error"), "mean_diff");
    EXPECT_EQ(j.at("time_unit"), "ms/frame");
    // 2 irradiance, 13 prefilter, 2 compensation, 4 shadows, 2 transmission, 3 anisotropy
    // and the path tracer at 1 spp (the series stops at 8 / 4).
    ASSERT_EQ(j.at("methods").size(), 27u);
    const bool rt = j["methods"].back().at("ran").get<bool>();
    if (!rt) GTEST_SKIP() << j["methods"].back().at("note");
    EXPECT_NE(j.at("reference").get<std::string>().find("8 spp"), std::string::npos);
    bool estimate = false;
    for (const auto& n : j.at("notes"))
        estimate |= n.get<std::string>().find("its estimated error") != std::string::npos;
    EXPECT_TRUE(estimate) << j.at("notes");
    std::set<std::string> groups;
    for (const auto& m : j.at("methods")) {
        groups.insert(m.at("group").get<std::string>());
        if (m.at("group") == "transmission" || m.at("group") == "anisotropy") {
            EXPECT_FALSE(m.at("ran").get<bool>());
            EXPECT_NE(m.at("note").get<std::string>().find("not applicable"), std::string::npos);
            continue;
        }
        ASSERT_TRUE(m.at("ran").get<bool>()) << m.at("name") << ": " << m.at("note");
        for (const char* e : {"mean_diff", "psnr_db", "material_0_mean_diff"})
            EXPECT_TRUE(m.at("errors").contains(e)) << m.at("name") << " " << e;
        EXPECT_TRUE(m.at("failures").empty()) << m.at("name");
    }
    EXPECT_EQ(groups,
              (std::set<std::string>{"irradiance", "specular prefilter", "energy compensation",
                                     "shadows", "transmission", "anisotropy", "path tracer"}));
    EXPECT_TRUE(j["methods"].back().at("errors").contains("ms_per_sample"));
    std::ifstream in(svg);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().rfind("<svg", 0), 0u);
    EXPECT_NE(text.str().find("irradiance sh9"), std::string::npos);
    fs::remove(svg);
    for (const char* bad : {"--reference-spp 0", "--width abc", "--height 5000", "--max-bounces -1",
                            "--reference-spp"})
        EXPECT_EQ(run_cli(std::string("lab builtin:default --family lighting ") + bad).exit_code, 2)
            << bad;
}

TEST(CliLab, CsvAndChart) {
    const fs::path svg =
        fs::temp_directory_path() / ("sherpa_lab_" + std::to_string(::getpid()) + ".svg");
    const auto r =
        run_cli("lab builtin:default --family tangents --csv --chart '" + svg.string() + "'",
                "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(r.out.rfind("method,parameters,ran,time,time_unit,total_ms,angle_mean_deg", 0), 0u)
        << r.out;
    std::ifstream in(svg);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().rfind("<svg", 0), 0u);
    EXPECT_NE(text.str().find("mikktspace-welded"), std::string::npos);
    fs::remove(svg);
}

TEST(CliLab, BadUsageAndBadFiles) {
    EXPECT_EQ(run_cli("lab builtin:default --family nope").exit_code, 2);
    EXPECT_EQ(run_cli("lab builtin:default").exit_code, 2) << "no family";
    EXPECT_EQ(run_cli("lab builtin:default --family tangents --json --csv").exit_code, 2);
    const auto r = run_cli("lab /no/such/file.gltf --family tangents");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.out.find("/no/such/file.gltf"), std::string::npos) << r.out;
    EXPECT_EQ(run_cli("compare builtin:default").exit_code, 2);
}

TEST(CliCompare, AFileAgainstItselfIsAllZeros) {
    const std::string duck = sherpa::test::gltf_asset("Duck");
    const auto r = run_cli("compare '" + duck + "' '" + duck + "' --json", "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& [name, c] : j["counts"].items()) EXPECT_EQ(c["a"], c["b"]) << name;
    ASSERT_FALSE(j["primitives"].empty());
    for (const auto& p : j["primitives"]) {
        EXPECT_EQ(p["vertices"][0], p["vertices"][1]);
        EXPECT_EQ(p["position_error"]["max"].get<double>(), 0.0);
        EXPECT_EQ(p["position_error"]["rms"].get<double>(), 0.0);
        EXPECT_EQ(p["normal_error_deg"]["max"].get<double>(), 0.0);
        EXPECT_EQ(p["uv_error"]["max"].get<double>(), 0.0);
    }
    EXPECT_TRUE(j["materials"].empty());
    ASSERT_FALSE(j["textures"].empty());
    for (const auto& t : j["textures"]) EXPECT_TRUE(t["identical"].get<bool>()) << t.dump();
    EXPECT_EQ(j["bytes"]["file"][0], j["bytes"]["file"][1]);
}

} // namespace

namespace {

TEST(CliBudget, RiggedSimpleJointsAreReadByMotionOnly) {
    const auto r = sherpa::test::run_cli(
        "budget '" + sherpa::test::gltf_asset("RiggedSimple") + "' --json", "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["categories"].size(), 5u);
    EXPECT_LE(j["categories"][0]["stored"].get<double>(),
              j["categories"][0]["unified"].get<double>());
    std::set<std::string> unread;
    for (const auto& u : j["unread_attributes"]) unread.insert(u["attribute"].get<std::string>());
    EXPECT_TRUE(unread.count("JOINTS_0") && unread.count("WEIGHTS_0"))
        << j["unread_attributes"].dump();
    EXPECT_EQ(sherpa::test::run_cli("budget").exit_code, 2);
}

} // namespace
