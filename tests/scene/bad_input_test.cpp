// Malformed input: a clear error naming the file and the problem, no partial
// scene; or, where glTF allows it, a warning and a usable scene. Plus mutation
// fuzzing: no input may crash or hang the importer.
#include "load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <random>

#include <gtest/gtest.h>

namespace {

namespace test = sherpa::test;

using test::BadCase;

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, FailsWithAClearMessageAndNoScene) {
    test::expect_clear_load_error((test::data_dir() / GetParam().file).string(),
                                  GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    MalformedFiles, BadInput,
    ::testing::Values(
        BadCase{"missing_buffer.gltf", "does_not_exist.bin"},
        BadCase{"short_buffer.gltf", "short_buffer.bin"},
        BadCase{"buffer_shorter_than_view.gltf", "exceeds buffers[0].byteLength 20"},
        BadCase{"bad_component_type.gltf", "componentType: 5130 is out of the range"},
        BadCase{"node_cycle.gltf", "cycle"}, BadCase{"node_self_child.gltf", "its own child"},
        BadCase{"node_two_parents.gltf", "child of both"},
        BadCase{"node_mesh_out_of_range.gltf", "nodes[0].mesh: mesh index 4 out of range"},
        BadCase{"unknown_required_extension.gltf", "EXT_made_up_required"},
        // named before the symptom (accessors without bufferView) is looked at
        BadCase{"unknown_required_extension_no_views.gltf",
                "extensionsRequired[0]: \"EXT_made_up_compression\" not supported"},
        BadCase{"bad_mode.gltf", "mode: 9"}, BadCase{"invalid_json.gltf", "parse error"},
        BadCase{"empty.gltf", "empty"}, BadCase{"truncated.glb", "binary"},
        BadCase{"no_such_file.gltf", "cannot open"}),
    test::case_name);

TEST(AllowedInput, PrimitiveWithoutMaterialUsesTheDefaultWithAWarning) {
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene((test::data_dir() / "no_material.gltf").string());
    ASSERT_TRUE(r) << r.error;
    const auto& mat = r.scene->materials.at(r.scene->meshes.at(0).material_id);
    EXPECT_EQ(mat.gltf_index, -1);
    ASSERT_EQ(r.scene->warnings.size(), 1u);
    EXPECT_NE(r.scene->warnings[0].find("no material"), std::string::npos);
}

// Load and warn: an unresolved default scene shows scene 0 and says so.
TEST(AllowedInput, DefaultSceneOutOfRangeShowsTheFirstScene) {
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene((test::data_dir() / "default_scene_out_of_range.gltf").string());
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->displayed_scene, 0);
    bool named = false;
    for (const auto& w : r.scene->warnings) named |= w.find("scene index 3") != std::string::npos;
    EXPECT_TRUE(named);
    bool khronos = false;
    for (const auto& m : r.scene->validation.messages)
        khronos |= m.code == "UNRESOLVED_REFERENCE" && m.pointer == "/scene";
    EXPECT_TRUE(khronos);
}

TEST(AllowedInput, EmptyPrimitiveIsSkippedWithoutInvertedBounds) {
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene((test::data_dir() / "empty_primitive.gltf").string());
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(r.scene->meshes.empty());
    EXPECT_TRUE(r.scene->instances.empty());
    EXPECT_FALSE(r.scene->bounds.valid()) << "no +-FLT_MAX box may reach later stages";
    EXPECT_EQ(r.scene->primitives.at(0).engine_mesh, -1);
    EXPECT_FALSE(r.scene->warnings.empty());
}

TEST(AllowedInput, PointsAreImportedAsPointsAndBounded) {
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene((test::data_dir() / "points.gltf").string());
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->meshes.size(), 1u);
    EXPECT_EQ(r.scene->meshes[0].topology(), sherpa::scene::Topology::Points);
    EXPECT_EQ(r.scene->meshes[0].element_count(), 3u);
    EXPECT_EQ(r.scene->meshes[0].triangle_count(), 0u);
    EXPECT_EQ(r.scene->counts.primitives, 1u);
    EXPECT_EQ(r.scene->counts.triangles, 0u);
    EXPECT_EQ(r.scene->node_primitive_pairs(), 1u) << "counted the glTF way";
    ASSERT_EQ(r.scene->instances.size(), 1u);
    EXPECT_EQ(r.scene->primitives.at(0).points, 3u);
    EXPECT_TRUE(r.scene->primitives.at(0).skipped_reason.empty());
    // The three points (0,0,0), (1,0,0), (0,1,0) span the scene bounds.
    ASSERT_TRUE(r.scene->bounds.valid());
    EXPECT_EQ(r.scene->bounds.min, glm::vec3(0.0f));
    EXPECT_EQ(r.scene->bounds.max, glm::vec3(1.0f, 1.0f, 0.0f));
}

// Random byte mutations of real files (text and binary) must each end in either a
// scene or an error: never a crash or a hang. Deterministic seeds.
void mutate_and_load(const std::string& source, const std::string& suffix, int rounds,
                     unsigned seed) {
    const auto original = test::read_bytes(source);
    ASSERT_FALSE(original.empty());
    const auto dir = std::filesystem::path(source).parent_path();
    const std::filesystem::path tmp =
        std::filesystem::temp_directory_path() / ("sherpa_fuzz_" + std::to_string(seed) + suffix);
    std::mt19937 rng(seed);
    int failures = 0;
    for (int round = 0; round < rounds; ++round) {
        auto bytes = original;
        const int edits = 1 + static_cast<int>(rng() % 8);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = rng() % bytes.size();
            switch (rng() % 4) {
            case 0:
                bytes[at] = static_cast<unsigned char>(rng());
                break;
            case 1:
                bytes[at] = static_cast<unsigned char>("0123456789-e.,[]{}\""[rng() % 19]);
                break;
            case 2:
                bytes.resize(at + 1);
                break;
            default:
                bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                             static_cast<unsigned char>(rng()));
                break;
            }
        }
        {
            std::ofstream f(tmp, std::ios::binary);
            f.write(reinterpret_cast<const char*>(bytes.data()),
                    static_cast<std::streamsize>(bytes.size()));
        }
        // Relative buffer URIs must still resolve: copy the file next to its .bin.
        const auto target = dir.empty() ? tmp : tmp;
        const sherpa::scene::LoadResult r = sherpa::scene::load_scene(target.string());
        if (!r) {
            ++failures;
            EXPECT_FALSE(r.error.empty());
        } else {
            for (const auto& inst : r.scene->instances) ASSERT_TRUE(inst.world_bounds.valid());
        }
    }
    std::filesystem::remove(tmp);
    EXPECT_GT(failures, 0) << "mutations should break at least some loads";
}

TEST(Fuzz, MutatedSelfContainedGltfNeverCrashes) {
    mutate_and_load((test::data_dir() / "lights_and_extensions.gltf").string(), ".gltf", 400, 1);
}

TEST(Fuzz, MutatedGlbNeverCrashes) {
    // A small GLB: build one from the embedded-buffer triangle by wrapping its JSON.
    const auto json_bytes = test::read_bytes(test::data_dir() / "two_scenes.gltf");
    std::vector<unsigned char> glb(12 + 8);
    std::vector<unsigned char> chunk = json_bytes;
    while (chunk.size() % 4) chunk.push_back(' ');
    auto put32 = [](std::vector<unsigned char>& v, std::size_t at, std::uint32_t x) {
        for (int i = 0; i < 4; ++i) v[at + i] = static_cast<unsigned char>(x >> (8 * i));
    };
    std::memcpy(glb.data(), "glTF", 4);
    put32(glb, 4, 2);
    put32(glb, 8, static_cast<std::uint32_t>(20 + chunk.size()));
    put32(glb, 12, static_cast<std::uint32_t>(chunk.size()));
    std::memcpy(glb.data() + 16, "JSON", 4);
    glb.insert(glb.end(), chunk.begin(), chunk.end());
    const auto path = std::filesystem::temp_directory_path() / "sherpa_fuzz_base.glb";
    {
        std::ofstream f(path, std::ios::binary);
        f.write(reinterpret_cast<const char*>(glb.data()),
                static_cast<std::streamsize>(glb.size()));
    }
    const sherpa::scene::LoadResult ok = sherpa::scene::load_scene(path.string());
    ASSERT_TRUE(ok) << ok.error;
    mutate_and_load(path.string(), ".glb", 400, 2);
    std::filesystem::remove(path);
}

// Broken parts that no longer refuse the file: it loads, and the part is named.
class BadInputLoadsNaming : public ::testing::TestWithParam<sherpa::test::BadCase> {};

TEST_P(BadInputLoadsNaming, LoadsAndNamesThePart) {
    sherpa::test::expect_loads_naming((sherpa::test::data_dir() / GetParam().file).string(),
                                      GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    LoadAndWarn, BadInputLoadsNaming,
    ::testing::Values(
        BadCase{"accessor_out_of_range.gltf", "attributes.POSITION: accessor index 7 out of range"},
        BadCase{"bufferview_out_of_range.gltf", "bufferView index 9 out of range"},
        BadCase{"accessor_past_view.gltf", "past the end of bufferViews[0]"},
        BadCase{"stride_too_small.gltf", "byteStride 4 is smaller"},
        BadCase{"normal_wrong_type.gltf", "attributes.NORMAL"},
        BadCase{"index_beyond_vertices.gltf", "= 5 is beyond the vertex count 3"},
        BadCase{"nan_position.gltf", "POSITION[1] is not finite"},
        BadCase{"inf_position.gltf", "POSITION[2] is not finite"},
        BadCase{"texture_out_of_range.gltf", "baseColorTexture.index: texture 3 out of range"}),
    sherpa::test::case_name);

} // namespace
