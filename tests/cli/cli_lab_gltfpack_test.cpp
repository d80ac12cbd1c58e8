// The Lab's mesh-compression family against an independent quantizer: gltfpack (npm,
// installed by the gltf_compress_corpus fixture) writes the sample model with
// KHR_mesh_quantization only (-vp 14 -vn 8 -vt 12 spelled out, no -c: no meshopt
// filters or octahedral normals; gltfpack never simplifies unless asked), and
// `sherpa-cli compare` of the source with that file must report the errors our
// method with the same bits predicts, within the quantization step; the bytes per
// vertex and the index bytes must be those gltfpack wrote. The fixture's gltfpack -cc
// file (EXT_meshopt_compression, 8-bit octahedral normals through the OCTAHEDRAL
// filter) is the reference of our quantized+meshopt-oct method.
#include "cli/cli_run.h"
#include "test_support.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

// The JSON chunk of a .glb.
nlohmann::json glb_json(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::uint32_t header[5] = {};
    in.read(reinterpret_cast<char*>(header), sizeof header);
    if (!in || header[0] != 0x46546C67u || header[4] != 0x4E4F534Au) return nullptr;
    std::string text(header[3], '\0');
    in.read(text.data(), std::streamsize(text.size()));
    return nlohmann::json::parse(text, nullptr, false);
}

// Bytes of the bufferViews with the given target (34962 vertices, 34963 indices).
double view_bytes(const nlohmann::json& gltf, int target) {
    double sum = 0;
    for (const auto& v : gltf.at("bufferViews"))
        if (v.value("target", 0) == target) sum += v.at("byteLength").get<double>();
    return sum;
}

// Errors of `method` (name, parameters vp=14 vn=8 vt=12) in `lab --json`.
nlohmann::json lab_errors(const std::string& source, const std::string& method) {
    const test::CliRun l =
        test::run_cli("lab '" + source + "' --family mesh-compression --json", "2>/dev/null");
    EXPECT_EQ(l.exit_code, 0) << l.out;
    const nlohmann::json lab = nlohmann::json::parse(l.out);
    for (const auto& m : lab.at("methods"))
        if (m["name"] == method && m["parameters"] == "vp=14 vn=8 vt=12") return m["errors"];
    return nullptr;
}

class LabAgainstGltfpack : public ::testing::TestWithParam<std::string> {};

TEST_P(LabAgainstGltfpack, SameBitsSameErrorsAndBytes) {
    const std::string model = GetParam(), source = test::gltf_asset(model);
    const fs::path packed = fs::temp_directory_path() /
                            ("sherpa_lab_" + model + "_" + std::to_string(::getpid()) + ".glb");
    const std::string gltfpack =
        std::string(SHERPA_GLTF_COMPRESS_CACHE) + "/gltfpack/node_modules/.bin/gltfpack";
    const std::string cmd = "'" + gltfpack + "' -i '" + source + "' -o '" + packed.string() +
                            "' -vp 14 -vn 8 -vt 12 >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

    const test::CliRun c =
        test::run_cli("compare '" + source + "' '" + packed.string() + "' --json", "2>/dev/null");
    ASSERT_EQ(c.exit_code, 0) << c.out;
    const auto cmp = nlohmann::json::parse(c.out);
    const nlohmann::json ours = lab_errors(source, "quantized");
    ASSERT_TRUE(ours.is_object());
    ASSERT_EQ(cmp.at("primitives").size(), 1u) << "one primitive in either file";
    const auto& p = cmp["primitives"][0];
    SCOPED_TRACE(p.dump() + "\nours: " + ours.dump());
    const double step = ours["position_step"].get<double>();
    // One mesh: gltfpack's grid (over the scene's meshes) is ours (over the mesh).
    EXPECT_LE(p["position_error"]["max"].get<double>(), step);
    EXPECT_LE(ours["position_max"].get<double>(), std::sqrt(3.0) / 2 * step);
    auto near = [](double theirs, double mine, const char* what) {
        EXPECT_GT(theirs, 0.0) << what;
        EXPECT_NEAR(theirs / mine, 1.0, 0.05)
            << what << ": gltfpack " << theirs << ", ours " << mine;
    };
    near(p["position_error"]["rms"].get<double>(), ours["position_rms"].get<double>(),
         "position RMS");
    near(p["position_error"]["max"].get<double>(), ours["position_max"].get<double>(),
         "position max");
    near(p["normal_error_deg"]["mean"].get<double>(), ours["normal_mean_deg"].get<double>(),
         "normal mean angle");
    near(p["uv_error"]["rms"].get<double>(), ours["uv_rms"].get<double>(), "uv RMS");

    const nlohmann::json gltf = glb_json(packed);
    ASSERT_TRUE(gltf.is_object());
    const auto& attributes = gltf["meshes"][0]["primitives"][0]["attributes"];
    const double vertices = gltf["accessors"][attributes["POSITION"].get<int>()]["count"];
    EXPECT_EQ(view_bytes(gltf, 34962) / vertices, ours["bytes_per_vertex"].get<double>());
    EXPECT_EQ(view_bytes(gltf, 34963), ours["index_bytes"].get<double>());
    fs::remove(packed);
}

TEST_P(LabAgainstGltfpack, CompressedFileMatchesTheOctahedralMethod) {
    const std::string model = GetParam(), source = test::gltf_asset(model);
    const fs::path packed =
        fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus" / (model + ".meshopt.glb");
    const test::CliRun c =
        test::run_cli("compare '" + source + "' '" + packed.string() + "' --json", "2>/dev/null");
    ASSERT_EQ(c.exit_code, 0) << c.out;
    const auto p = nlohmann::json::parse(c.out).at("primitives").at(0);
    const nlohmann::json ours = lab_errors(source, "quantized+meshopt-oct");
    ASSERT_TRUE(ours.is_object());
    SCOPED_TRACE(p.dump() + "\nours: " + ours.dump());
    for (auto [theirs, mine] : {std::pair{p["position_error"]["rms"], ours["position_rms"]},
                                std::pair{p["normal_error_deg"]["mean"], ours["normal_mean_deg"]},
                                std::pair{p["normal_error_deg"]["max"], ours["normal_max_deg"]},
                                std::pair{p["uv_error"]["rms"], ours["uv_rms"]}})
        EXPECT_NEAR(theirs.get<double>() / mine.get<double>(), 1.0, 0.15);
    // Encoded bytes: gltfpack also reorders vertices for the codec, which we do not, so
    // only the order of magnitude is shared.
    double vertex = 0, index = 0;
    const nlohmann::json gltf = glb_json(packed);
    ASSERT_TRUE(gltf.is_object());
    for (const auto& v : gltf.at("bufferViews")) {
        if (!v.contains("extensions") || !v["extensions"].contains("EXT_meshopt_compression"))
            continue;
        const auto& e = v["extensions"]["EXT_meshopt_compression"];
        (e["mode"] == "ATTRIBUTES" ? vertex : index) += e["byteLength"].get<double>();
    }
    const double theirs = vertex + index, mine = ours["bytes"].get<double>();
    EXPECT_GT(mine / theirs, 0.8) << "ours " << mine << ", gltfpack " << theirs;
    EXPECT_LT(mine / theirs, 1.5) << "ours " << mine << ", gltfpack " << theirs;
}

INSTANTIATE_TEST_SUITE_P(Models, LabAgainstGltfpack, ::testing::Values("Duck", "DamagedHelmet"));

} // namespace
