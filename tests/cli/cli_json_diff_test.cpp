// `sherpa-cli compare A B`'s json_diff on real pairs: a sample model against its
// gltfpack and gltf-transform (Draco) versions from the gltf_compress_corpus fixture,
// and a hand-edited copy, in text and --json.
#include "cli/cli_run.h"
#include "test_support.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

nlohmann::json compare_json(const std::string& a, const std::string& b) {
    const test::CliRun r = test::run_cli("compare '" + a + "' '" + b + "' --json", "2>/dev/null");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

const nlohmann::json* drift_of(const nlohmann::json& diff, const std::string& use) {
    for (const auto& d : diff["accessor_drift"])
        if (d["use"] == use) return &d;
    return nullptr;
}

bool has(const nlohmann::json& list, const std::string& pointer) {
    for (const auto& p : list)
        if ((p.is_string() ? p : p["pointer"]) == pointer) return true;
    return false;
}

std::string corpus(const std::string& name) {
    return (fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus" / name).string();
}

// gltfpack renumbers accessors and quantizes positions to unnormalized 14-bit
// integers (the node transform dequantizes): the drift follows the use and says the
// bounds are not comparable.
TEST(CliJsonDiff, GltfpackQuantizationIsNamedPerUse) {
    const auto j = compare_json(test::gltf_asset("Duck"), corpus("Duck.meshopt.glb"));
    ASSERT_TRUE(j.contains("json_diff"));
    const auto& diff = j["json_diff"];
    EXPECT_TRUE(has(diff["added"], "/extensionsUsed"));
    EXPECT_TRUE(has(diff["changed"], "/nodes/0"));
    const auto* position = drift_of(diff, "/meshes/0/primitives/0/attributes/POSITION");
    ASSERT_TRUE(position) << diff.dump(1);
    EXPECT_EQ((*position)["accessor"], nlohmann::json({2, 1}));
    EXPECT_FALSE((*position)["comparable"].get<bool>());
    EXPECT_TRUE((*position)["drift"].is_null());
    EXPECT_NE((*position)["note"].get<std::string>().find("FLOAT -> UNSIGNED_SHORT"),
              std::string::npos);
    // Octahedral normals: normalized bytes (a float value space), but gltfpack
    // writes no bounds for them: said, not guessed.
    const auto* normal = drift_of(diff, "/meshes/0/primitives/0/attributes/NORMAL");
    ASSERT_TRUE(normal);
    EXPECT_NE((*normal)["note"].get<std::string>().find("B declares no min/max"),
              std::string::npos);
}

// gltf-transform's Draco output keeps accessor indices and the POSITION bounds
// (required); it drops the optional bounds of the other accessors, which is said.
TEST(CliJsonDiff, DracoKeepsThePositionBounds) {
    const auto j = compare_json(test::gltf_asset("Duck"), corpus("Duck.draco.glb"));
    const auto& diff = j["json_diff"];
    EXPECT_TRUE(has(diff["added"], "/extensionsUsed"));
    EXPECT_TRUE(has(diff["changed"], "/meshes/0"));
    EXPECT_FALSE(drift_of(diff, "/meshes/0/primitives/0/attributes/POSITION")) << diff.dump(1);
    for (const auto& d : diff["accessor_drift"]) {
        EXPECT_EQ(d["accessor"][0], d["accessor"][1]) << d.dump();
        EXPECT_EQ(d["note"], "B declares no min/max") << d.dump();
    }
    bool extension_named = false;
    for (const auto& c : diff["changed"])
        if (c["pointer"] == "/meshes/0")
            for (const auto& f : c["fields"])
                extension_named |= f.get<std::string>().find("/primitives/0/extensions: added") !=
                                   std::string::npos;
    EXPECT_TRUE(extension_named) << diff.dump(1);
}

// A copy of BoxTextured with one edit: the text output names it by pointer.
TEST(CliJsonDiff, HandEditShowsInTextAndJson) {
    const fs::path dir =
        fs::temp_directory_path() / ("sherpa_json_diff_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path src = fs::path(test::gltf_asset("BoxTextured")).parent_path();
    for (const char* f : {"BoxTextured0.bin", "CesiumLogoFlat.png"})
        fs::copy_file(src / f, dir / f, fs::copy_options::overwrite_existing);
    nlohmann::json doc = test::read_json(test::gltf_asset("BoxTextured"));
    doc["accessors"][2]["min"][1] = -0.625; // POSITION min y -0.5 -> -0.625
    doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.25;
    const fs::path edited = dir / "BoxTextured.gltf";
    std::ofstream(edited) << doc.dump(1);

    const test::CliRun r =
        test::run_cli("compare '" + test::gltf_asset("BoxTextured") + "' '" + edited.string() + "'",
                      "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("json_diff: 0 added, 0 removed, 2 changed"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("/pbrMetallicRoughness/roughnessFactor: added 0.25"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("min/max  /meshes/0/primitives/0/attributes/POSITION (accessor 2 -> 2): "
                         "drift 0.125 (12.5% of the extent)"),
              std::string::npos)
        << r.out;
    const auto j = compare_json(test::gltf_asset("BoxTextured"), edited.string());
    EXPECT_EQ(j["json_diff"]["accessor_drift"].size(), 1u);
    EXPECT_DOUBLE_EQ(j["json_diff"]["accessor_drift"][0]["drift"].get<double>(), 0.125);
    fs::remove_all(dir);
}

} // namespace
