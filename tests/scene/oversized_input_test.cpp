// Numbers in the file that the bytes behind them do not back, and integers tinygltf
// would wrap: extension properties (meshopt streams, Draco ids, texture image
// extensions, material textureInfo) are checked in the raw JSON like the core ones,
// and a meshopt view allocates what its stream decodes, not what its fallback buffer
// declares, and a Draco stream's counts are bounded before Draco allocates by them.
// Reproducers: tests/data/make_oversized.py. The same files under a 2 GB address-space
// limit through sherpa-cli: tests/cli/memory_limit_test.sh.
#include "load_error_check.h"
#include "peak_rss.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include <unistd.h>

namespace {

namespace test = sherpa::test;
using nlohmann::json;

constexpr std::uint64_t k2p32 = std::uint64_t{1} << 32;

// A copy of tests/data/`base` with `value` put at JSON pointer `pointer`.
std::string edited(const std::string& base, const std::string& pointer, const json& value,
                   const std::string& name) {
    json doc = test::read_json((test::data_dir() / base).string());
    doc[json::json_pointer(pointer)] = value;
    const auto dir =
        std::filesystem::temp_directory_path() / ("sherpa_oversized_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".gltf")).string();
    std::ofstream(path) << doc.dump();
    return path;
}

struct Edit {
    const char* name;
    const char* base;
    const char* pointer;
    json value;
    const char* message;
};

class WrappingInteger : public ::testing::TestWithParam<Edit> {};

// Each value once loaded as wrong data without a word (2^32 became 0, 2^32 + 3
// became 3, 0.5 became 0); now the load fails naming the property's JSON path.
TEST_P(WrappingInteger, IsRefusedWithItsJsonPath) {
    const Edit& e = GetParam();
    test::expect_clear_load_error(edited(e.base, e.pointer, e.value, e.name), e.message);
}

constexpr const char* kMeshopt = "meshopt_fallback_1800mb.gltf";
constexpr const char* kImages = "image_bombs.gltf";
#define MESHOPT_EXT "/bufferViews/0/extensions/EXT_meshopt_compression/"
#define MESHOPT_PATH "bufferViews[0].extensions.EXT_meshopt_compression."
#define DRACO_EXT "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression"
#define DRACO_PATH "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression."

INSTANTIATE_TEST_SUITE_P(
    ExtensionProperties, WrappingInteger,
    ::testing::Values(
        Edit{"meshopt_count", kMeshopt, MESHOPT_EXT "count", k2p32 + 3,
             MESHOPT_PATH "count: 4294967299 is out of the range 0..2147483647"},
        Edit{"meshopt_offset", kMeshopt, MESHOPT_EXT "byteOffset", k2p32,
             MESHOPT_PATH "byteOffset: 4294967296 is out of the range"},
        Edit{"meshopt_length", kMeshopt, MESHOPT_EXT "byteLength", k2p32 + 45,
             MESHOPT_PATH "byteLength: 4294967341 is out of the range"},
        Edit{"meshopt_stride", kMeshopt, MESHOPT_EXT "byteStride", k2p32 + 12,
             MESHOPT_PATH "byteStride: 4294967308 is out of the range 1..256"},
        Edit{"meshopt_count_fraction", kMeshopt, MESHOPT_EXT "count", 3.5,
             MESHOPT_PATH "count: 3.5 is not a non-negative integer"},
        Edit{"meshopt_fallback_string", kMeshopt,
             "/buffers/1/extensions/EXT_meshopt_compression/fallback", "yes",
             "buffers[1].extensions.EXT_meshopt_compression.fallback: \"yes\" is not a boolean"},
        Edit{"draco_view", kImages, DRACO_EXT,
             json{{"bufferView", k2p32}, {"attributes", {{"POSITION", 0}}}},
             DRACO_PATH "bufferView: 4294967296 is out of the range"},
        Edit{"draco_attribute", kImages, DRACO_EXT,
             json{{"bufferView", 0}, {"attributes", {{"POSITION", k2p32}}}},
             DRACO_PATH "attributes.POSITION: 4294967296 is out of the range"},
        Edit{"basisu_source", kImages, "/textures/3/extensions/KHR_texture_basisu/source", k2p32,
             "textures[3].extensions.KHR_texture_basisu.source: 4294967296 is out of the range"},
        Edit{"basisu_source_half", kImages, "/textures/3/extensions/KHR_texture_basisu/source", 0.5,
             "textures[3].extensions.KHR_texture_basisu.source: 0.5 is not a non-negative"},
        Edit{"webp_source", kImages, "/textures/2/extensions/EXT_texture_webp/source", -1,
             "textures[2].extensions.EXT_texture_webp.source: -1 is not a non-negative"},
        Edit{"texture_index", kImages, "/materials/0/pbrMetallicRoughness/baseColorTexture/index",
             k2p32,
             "materials[0].pbrMetallicRoughness.baseColorTexture.index: 4294967296 is out of"},
        Edit{"tex_coord", kImages, "/materials/0/normalTexture/texCoord", k2p32,
             "materials[0].normalTexture.texCoord: 4294967296 is out of the range"},
        Edit{"transform_tex_coord", kImages,
             "/materials/0/emissiveTexture/extensions/KHR_texture_transform/texCoord", k2p32 + 1,
             "materials[0].emissiveTexture.extensions.KHR_texture_transform.texCoord: 4294967297"},
        Edit{"extension_texture_index", kImages,
             "/materials/0/extensions/KHR_materials_clearcoat/clearcoatTexture",
             json{{"index", k2p32}},
             "materials[0].extensions.KHR_materials_clearcoat.clearcoatTexture.index: 4294967296"},
        Edit{"texture_index_missing", kImages, "/materials/0/occlusionTexture",
             json{{"texCoord", 0}},
             "materials[0].occlusionTexture.index: required property is missing"}),
    [](const ::testing::TestParamInfo<Edit>& param_info) {
        return std::string(param_info.param.name);
    });

// The view declares 1.8 GB (its fallback buffer has no bytes); the stream decodes 3
// positions. Before, the importer filled the declared byteLength (1.84 GB of RSS); the
// address-space half of this test is tests/cli/memory_limit_test.sh.
TEST(OversizedMeshopt, FallbackBufferDeclaringGigabytesLoadsWhatTheStreamDecodes) {
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene((test::data_dir() / "meshopt_fallback_1800mb.gltf").string());
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->primitives.size(), 1u);
    ASSERT_TRUE(r.scene->primitives[0].compression.has_value());
    EXPECT_EQ(r.scene->primitives[0].compression->decoded_bytes, 36u);
    EXPECT_EQ(r.scene->primitives[0].vertices, 3u);
}

// 100000 x 12 bytes cannot come from 45 bytes (a version 0 vertex stream of that many
// elements needs at least its blocks' header bits): nothing is allocated or decoded,
// and the primitive reading the view is skipped by name; the file loads.
TEST(OversizedMeshopt, CountTheStreamCannotHoldSkipsItsPrimitiveBeforeAllocating) {
    test::expect_primitive_skipped(
        edited(kMeshopt, MESHOPT_EXT "count", 100000, "meshopt_count_unbacked"), 0, 0,
        "/bufferViews/0/extensions/EXT_meshopt_compression",
        "bufferViews[0].extensions.EXT_meshopt_compression: count 100000 x byteStride 12 = "
        "1200000 bytes cannot come from a 45-byte ATTRIBUTES stream");
}

// An accessor reading past what the stream decodes is refused, not shown zeros.
// The file loads (the inspector shows what it can); the primitive that reads past the
// decoded bytes is skipped, with the reason naming the view.
TEST(OversizedMeshopt, AccessorPastTheDecodedBytesSkipsItsPrimitiveByName) {
    const auto r = sherpa::scene::load_scene(
        edited(kMeshopt, "/accessors/0/byteOffset", 12, "meshopt_accessor_past"));
    ASSERT_TRUE(r) << r.error;
    ASSERT_FALSE(r.scene->primitives.empty());
    EXPECT_NE(r.scene->primitives[0].skipped_reason.find("past the end of bufferViews[0]"),
              std::string::npos)
        << r.scene->primitives[0].skipped_reason;
}

#define DRACO_STREAM                                                                               \
    "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: the Draco stream "
constexpr const char* kDracoPointer =
    "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression";

// Box's 130-byte Edgebreaker stream declaring 2^28 triangles and symbols (Draco checks
// the counts against each other, not against the bytes behind the symbols): Draco
// 1.5.5 sized its corner table by them (6 GB) before it read one symbol, and under a
// memory limit the load failed "out of memory while importing". Now the primitive is
// skipped by name before decoding, and the rest of the file loads.
TEST(OversizedDraco, TrianglesPastTheIndicesSkipThePrimitiveBeforeDecoding) {
    test::expect_primitive_skipped(
        (test::data_dir() / "draco_faces_268m.gltf").string(), 0, 0, kDracoPointer,
        DRACO_STREAM "(bufferViews[0], 138 bytes) declares 268435456 triangles (805306368 "
                     "indices), more than the indices accessor's count 36");
}

// 20M triangles whose indices accessor agrees, over the documented limit. Draco
// allocated and filled its corner table (470 MB of RSS, 596 MB peak for sherpa-cli
// info) before finding that 136 bytes hold no such traversal; now nothing is decoded.
TEST(OversizedDraco, TrianglesOverTheLimitSkipThePrimitiveWithoutAllocating) {
    const std::string path = (test::data_dir() / "draco_faces_20m.gltf").string();
    const long growth = test::peak_rss_growth_kib([&] {
        test::expect_primitive_skipped(path, 0, 0, kDracoPointer,
                                       DRACO_STREAM "(bufferViews[0], 136 bytes) declares "
                                                    "20000000 triangles; Sherpa decodes at most "
                                                    "16777216 triangles per Draco primitive");
    });
    if (growth < 0) GTEST_SKIP() << "no /proc/self/clear_refs: peak RSS not measured";
    EXPECT_LT(growth, 32 * 1024) << "peak RSS grew by " << growth << " KiB";
}

// One attribute connectivity (a corner table each, once the traversal decodes) per
// attribute at most: 255 for a primitive of two attributes skips it.
TEST(OversizedDraco, MoreAttributeConnectivitiesThanAttributesSkipThePrimitive) {
    test::expect_primitive_skipped(
        (test::data_dir() / "draco_attribute_data_255.gltf").string(), 0, 0, kDracoPointer,
        DRACO_STREAM "(bufferViews[0], 130 bytes) declares 255 attribute connectivities for 2 "
                     "attributes");
}

// Every importer reproducer the fuzzer saved (tests/fuzz/findings, README there: out-of-
// bounds reads, an exception escaping tinygltf, tinygltf's stack overflow) loads or
// fails with a message; under the sanitizer build (build-asan) with no report.
TEST(FuzzFindings, ImporterReproducersLoadOrFailWithAReason) {
    int replayed = 0;
    for (const auto& dir :
         std::filesystem::directory_iterator(test::data_dir() / "../fuzz/findings"))
        for (const char* name : {"__case.gltf", "__case.glb"}) {
            const auto file = dir.path() / name;
            if (!std::filesystem::exists(file)) continue;
            const sherpa::scene::LoadResult r = sherpa::scene::load_scene(file.string());
            EXPECT_TRUE(r || !r.error.empty()) << file;
            ++replayed;
        }
    EXPECT_GE(replayed, 6);
}

} // namespace
