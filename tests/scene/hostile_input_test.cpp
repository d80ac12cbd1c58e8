// Hostile input (issue #12): files that crashed, exhausted memory or loaded as
// silent garbage. Each reproducer lives in tests/data (make_malformed.py writes
// them); docs/robustness.md lists them with what Sherpa does now. What sherpa-cli
// makes of them: tests/cli/cli_hostile_test.cpp.
#include "load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/image_sources.h>
#include <sherpa/scene/scene_loader.h>

#include <cmath>
#include <cstdio>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "checked_math.h" // engine/scene/src: the overflow-proof size helpers

namespace {

namespace test = sherpa::test;

using test::BadCase;
using test::expect_clear_load_error;

class HostileFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(HostileFile, FailsWithAClearMessage) {
    expect_clear_load_error((test::data_dir() / GetParam().file).string(), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Issue12, HostileFile,
    ::testing::Values(
        BadCase{"view_offset_wraps.gltf",
                "bufferViews[0].byteOffset: 18446744073709551600 is out of the range"},
        BadCase{"negative_byte_offset.gltf",
                "accessors[0].byteOffset: -12 is not a non-negative integer"},
        BadCase{"string_byte_offset.gltf",
                "accessors[0].byteOffset: \"12\" is not a non-negative integer"},
        BadCase{"fractional_byte_length.gltf", "byteLength: 36.5 is not a non-negative"},
        BadCase{"buffer_uri_dot.gltf", ". : is a directory"},
        BadCase{"buffer_uri_parent.gltf", "../ : is a directory"},
        BadCase{"buffer_uri_root.gltf", "/ : is a directory"},
        BadCase{"buffer_uri_nul.gltf", "buffers[0].uri \"a%00\": contains a NUL byte"},
        BadCase{"buffer_uri_bad_escape.gltf", "malformed percent escape"},
        BadCase{"version_3.gltf", "asset.version \"3.0\""},
        BadCase{"deep_nesting.gltf", "JSON nests deeper than 256 levels"},
        BadCase{"deep_nesting.glb", "JSON nests deeper than 256 levels"},
        BadCase{"png_renamed.gltf", "not a glTF file: starts with PNG image bytes"},
        BadCase{"image_view_past_buffer.glb",
                "bufferViews[2]: byteOffset 44 + byteLength 4096 exceeds buffers[0]"}),
    test::case_name);

TEST(HostileSizes, CheckedArithmeticNeverWraps) {
    using namespace sherpa::scene::detail;
    constexpr std::size_t near_max = SIZE_MAX - 15; // the wrapped check passed this
    static_assert(!range_fits(near_max, 32, 100));
    static_assert(range_fits(68, 0, 68) && !range_fits(69, 0, 68));
    static_assert(!checked_add(near_max, 16).has_value());
    static_assert(!checked_mul(std::size_t{1} << 40, std::size_t{1} << 30).has_value());
    static_assert(checked_mul(252, 1000).value() == 252000);
}

std::filesystem::path scratch_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("sherpa_hostile_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(HostilePaths, DirectoryAsSceneSaysSo) {
    const auto dir = scratch_dir("dir");
    const auto scene = dir / "looks_like.gltf";
    std::filesystem::create_directory(scene);
    expect_clear_load_error(scene.string(), "is a directory, not a glTF file");
    std::filesystem::remove_all(dir);
}

// A FIFO blocked the reader forever in open(); it must be refused, as SCENE and as
// a buffer URI (ctest's timeout catches a hang).
TEST(HostilePaths, FifoAsSceneOrBufferIsRefusedWithoutBlocking) {
    const auto dir = scratch_dir("fifo");
    ASSERT_EQ(::mkfifo((dir / "pipe.gltf").c_str(), 0600), 0);
    expect_clear_load_error((dir / "pipe.gltf").string(), "is a FIFO (named pipe)");
    ASSERT_EQ(::mkfifo((dir / "data.bin").c_str(), 0600), 0);
    auto doc = test::read_json((test::data_dir() / "missing_buffer.gltf").string());
    doc["buffers"][0]["uri"] = "data.bin";
    std::ofstream(dir / "fifo_buffer.gltf") << doc.dump();
    expect_clear_load_error((dir / "fifo_buffer.gltf").string(), "is a FIFO (named pipe)");
    std::filesystem::remove_all(dir);
}

sherpa::scene::LoadResult load_data(const char* file) {
    return sherpa::scene::load_scene((test::data_dir() / file).string());
}

bool has_warning(const sherpa::scene::Scene& s, const std::string& fragment) {
    for (const auto& w : s.warnings)
        if (w.find(fragment) != std::string::npos) return true;
    return false;
}

// One odd object must not refuse a valid file: it is skipped with a warning.
TEST(HostileObjects, InvalidCamerasAreSkippedWithAWarning) {
    for (const char* file :
         {"camera_zfar_below_znear.gltf", "camera_negative_xmag.gltf", "camera_yfov_pi.gltf"}) {
        const auto r = load_data(file);
        ASSERT_TRUE(r) << file << ": " << r.error;
        EXPECT_EQ(r.scene->cameras.size(), 1u) << file;
        EXPECT_TRUE(r.scene->placed_cameras.empty()) << file << ": never rendered blank";
        EXPECT_TRUE(has_warning(*r.scene, "cameras[0]")) << file;
        EXPECT_TRUE(has_warning(*r.scene, "camera skipped")) << file;
        EXPECT_EQ(r.scene->instances.size(), 1u) << file;
    }
}

TEST(HostileObjects, InvalidLightsAreSkippedWithAWarning) {
    for (const char* file :
         {"light_negative_intensity.gltf", "light_cone_inverted.gltf", "light_unknown_type.gltf"}) {
        const auto r = load_data(file);
        ASSERT_TRUE(r) << file << ": " << r.error;
        EXPECT_EQ(r.scene->lights.size(), 1u) << file;
        EXPECT_TRUE(r.scene->placed_lights.empty()) << file;
        EXPECT_TRUE(has_warning(*r.scene, "lights[0]")) << file;
        EXPECT_TRUE(has_warning(*r.scene, "light skipped")) << file;
    }
}

TEST(HostileObjects, HugeNormalScaleIsClamped) {
    const auto r = load_data("normal_scale_huge.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->materials.at(0).normal_scale, 1000.0f);
    EXPECT_TRUE(has_warning(*r.scene, "normalTexture.scale: 1e+30"));
}

TEST(HostileObjects, NanAndZeroNormalsGetTheirFaceNormal) {
    const auto r = load_data("nan_normals.gltf");
    ASSERT_TRUE(r) << r.error;
    for (const auto& v : r.scene->meshes.at(0).vertices) {
        EXPECT_TRUE(std::isfinite(v.normal.z));
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f) << "the triangle lies in z = 0";
    }
    EXPECT_TRUE(has_warning(*r.scene, "2 zero-length or NaN normals replaced"));
}

TEST(HostileObjects, RepeatedSceneRootsAreShownOnce) {
    const auto r = load_data("duplicate_scene_roots.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->instances.size(), 1u);
    EXPECT_TRUE(has_warning(*r.scene, "2 repeated root node(s) ignored"));
}

// Finite transforms times finite positions past the float range: that instance is not
// drawn (its vertices would reach the rasterizer as infinities), by name and pointer;
// the file loads with the rest of its scene.
TEST(HostileObjects, WorldBoundsPastTheFloatRangeLeaveTheInstanceOut) {
    const auto r = load_data("world_bounds_overflow.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(r.scene->instances.empty());
    EXPECT_EQ(r.scene->nodes.size(), 1u);
    EXPECT_TRUE(has_warning(*r.scene, "nodes[0]: world bounds of its mesh overflow the float "
                                      "range (node transform x positions); the instance is not "
                                      "drawn"));
    std::size_t said = 0;
    for (const auto& m : r.scene->validation.messages)
        if (m.code == "SHERPA_INSTANCE_SKIPPED") {
            ++said;
            EXPECT_EQ(m.pointer, "/nodes/0");
            EXPECT_EQ(m.severity, sherpa::scene::Severity::Warning);
        }
    EXPECT_EQ(said, 1u);
    // Selecting the scene again says it once, not once per selection.
    std::string error;
    ASSERT_TRUE(sherpa::scene::select_scene(*r.scene, 0, error)) << error;
    std::size_t lines = 0;
    for (const auto& w : r.scene->warnings) lines += w.find("overflow the float") != w.npos;
    EXPECT_EQ(lines, 1u);
}

// glTF requires exact min/max: data outside them is reported (warning and
// Scene::range_violations), and kept as it is. `info --json` reports it too:
// tests/cli/cli_hostile_test.cpp.
TEST(HostileObjects, DataOutsideDeclaredMinMaxIsReported) {
    const auto r = load_data("position_outside_minmax.gltf");
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->range_violations.size(), 1u);
    const auto& v = r.scene->range_violations[0];
    EXPECT_EQ(v.accessor, 0);
    EXPECT_EQ(v.elements_outside, 1u);
    EXPECT_EQ(v.declared_max.at(2), 0.5);
    EXPECT_FLOAT_EQ(v.data_max.at(2), 1.7e38f);
    EXPECT_TRUE(has_warning(*r.scene, "outside the declared min"));
}

TEST(HostileObjects, ImageUriNamingADirectoryLeavesTheImageEmptyWithAWarning) {
    const auto r = load_data("image_uri_directory.gltf");
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(r.scene->images.at(0).encoded.empty());
    // Said once, by the texture pipeline's "missing" note (not again as tinygltf's line).
    EXPECT_EQ(image_missing_reason(*r.scene, r.scene->images.at(0)), "is a directory, not a file");
}

// Image bytes in a .glb's BIN chunk are taken by Sherpa, range-checked: compare with
// the bufferView's bytes as an independent JSON reader locates them.
TEST(HostileObjects, GlbImageBytesComeFromTheirBufferView) {
    const auto path = test::data_dir() / "image_in_glb.glb";
    const auto r = sherpa::scene::load_scene(path.string());
    ASSERT_TRUE(r) << r.error;
    const auto bytes = test::read_bytes(path);
    const auto json_length = static_cast<std::size_t>(bytes[12] | bytes[13] << 8);
    const auto doc = nlohmann::json::parse(bytes.begin() + 20,
                                           bytes.begin() + 20 + static_cast<long>(json_length));
    const auto& view = doc["bufferViews"][doc["images"][0]["bufferView"].get<int>()];
    const std::size_t bin = 20 + json_length + 8 + view["byteOffset"].get<std::size_t>();
    const std::vector<unsigned char> expected(
        bytes.begin() + static_cast<long>(bin),
        bytes.begin() + static_cast<long>(bin + view["byteLength"].get<std::size_t>()));
    const auto& encoded = r.scene->images.at(0).encoded;
    EXPECT_EQ(std::vector<unsigned char>(encoded.begin(), encoded.end()), expected);
}

// Broken parts that no longer refuse the file: it loads, and the part is named.
class Issue12LoadsNaming : public ::testing::TestWithParam<sherpa::test::BadCase> {};

TEST_P(Issue12LoadsNaming, LoadsAndNamesThePart) {
    sherpa::test::expect_loads_naming((sherpa::test::data_dir() / GetParam().file).string(),
                                      GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    LoadAndWarn, Issue12LoadsNaming,
    ::testing::Values(
        BadCase{"min_version_2_1.gltf", "minVersion \"2.1\""},
        BadCase{"huge_count.gltf", "reads 804000000 bytes at offset 0 past the end"},
        BadCase{"zero_fill_count.gltf", "count 60000000 without a bufferView (all zeros) exceeds"},
        BadCase{"sparse_index_max.gltf", "[2] = 4294967295 is beyond the vertex count 3"},
        BadCase{"sparse_index_2p24.gltf", "[2] = 16777217 is beyond the vertex count 3"},
        BadCase{"sparse_indices_normalized.gltf", "indices must not be normalized"}),
    sherpa::test::case_name);

} // namespace
