// The glTF validator (Khronos codes, JSON pointers) and load-and-warn: files with
// problems load and name them. tests/data/validation holds one file per code
// (tools/gltf_validator/make_cases.py); the Khronos validator's verdict on each is the
// oracle test (validation_oracle_agreement); these pin the cases that decide loading.
#include "validation_checks.h"

#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include "validate_internal.h" // engine/scene/src: pointer_of_path

namespace {

namespace test = sherpa::test;
using sherpa::scene::Severity;
using sherpa::scene::ValidationReport;

using test::case_path;
using test::dump;
using test::Expect;
using test::has;

TEST(Validation, ValidFileHasNoErrorsOrWarnings) {
    const auto r = sherpa::scene::load_scene(case_path("valid.gltf"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->validation.count(Severity::Error), 0u) << dump(r.scene->validation);
    EXPECT_EQ(r.scene->validation.count(Severity::Warning), 0u) << dump(r.scene->validation);
    EXPECT_GT(r.scene->validation.ms, 0.0);
}

// Each: file, a code with its pointer that must be reported, and the file must load.

class LoadsWithMessage : public ::testing::TestWithParam<Expect> {};

TEST_P(LoadsWithMessage, AndNamesIt) {
    const auto r = sherpa::scene::load_scene(case_path(GetParam().file));
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(has(r.scene->validation, GetParam().code, GetParam().pointer))
        << dump(r.scene->validation);
}

INSTANTIATE_TEST_SUITE_P(
    Codes, LoadsWithMessage,
    ::testing::Values(
        Expect{"accessor_min_mismatch.gltf", "ACCESSOR_MIN_MISMATCH", "/accessors/0/min/0"},
        Expect{"accessor_out_of_max.gltf", "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND",
               "/accessors/0/max/0"},
        Expect{"accessor_normal_non_unit.gltf", "ACCESSOR_VECTOR3_NON_UNIT",
               "/meshes/0/primitives/0/attributes/NORMAL"},
        Expect{"anim_input_non_increasing.gltf", "ACCESSOR_ANIMATION_INPUT_NON_INCREASING",
               "/animations/0/samplers/0/input"},
        Expect{"anim_input_non_increasing.gltf", "SHERPA_ANIMATION_CHANNEL_SKIPPED",
               "/animations/0/samplers/0/input"},
        Expect{"anim_quaternion_non_unit.gltf",
               "ACCESSOR_ANIMATION_SAMPLER_OUTPUT_NON_NORMALIZED_QUATERNION",
               "/animations/0/channels/0/sampler"},
        Expect{"anim_bad_interpolation.gltf", "VALUE_NOT_IN_LIST",
               "/animations/0/samplers/0/interpolation"},
        Expect{"bad_alpha_mode.gltf", "VALUE_NOT_IN_LIST", "/materials/0/alphaMode"},
        Expect{"unresolved_accessor.gltf", "UNRESOLVED_REFERENCE",
               "/meshes/0/primitives/0/attributes/NORMAL"},
        Expect{"node_matrix_non_trs.gltf", "NODE_MATRIX_NON_TRS", "/nodes/0/matrix"},
        Expect{"camera_zfar.gltf", "CAMERA_ZFAR_LEQUAL_ZNEAR", "/cameras/0/perspective"},
        Expect{"weights_non_normalized.gltf", "ACCESSOR_WEIGHTS_NON_NORMALIZED",
               "/meshes/1/primitives/0/attributes/WEIGHTS_0"},
        Expect{"index_oob.gltf", "ACCESSOR_INDEX_OOB", "/meshes/0/primitives/0/indices"},
        Expect{"min_version_greater.gltf", "ASSET_MIN_VERSION_GREATER_THAN_VERSION",
               "/asset/minVersion"},
        Expect{"unexpected_property.gltf", "UNEXPECTED_PROPERTY", "/nodes/0/foo"},
        Expect{"undeclared_extension.gltf", "UNDECLARED_EXTENSION", "/nodes/0/extensions/KHR_foo"},
        Expect{"glb_extra_data.glb", "GLB_EXTRA_DATA", ""},
        Expect{"glb_data_uri.glb", "DATA_URI_GLB", "/buffers/0/uri"},
        // First use wins; a different later use is the Khronos override error.
        Expect{"anim_input_format.gltf", "ACCESSOR_USAGE_OVERRIDE",
               "/animations/0/samplers/0/output"},
        Expect{"image_mime_missing.gltf", "BUFFER_VIEW_TARGET_OVERRIDE",
               "/animations/0/samplers/0/input"},
        Expect{"accessor_offset_alignment.gltf", "MESH_PRIMITIVE_ACCESSOR_UNALIGNED",
               "/meshes/0/primitives/0/attributes/TEXCOORD_0"},
        Expect{"tangent_without_normal.gltf", "MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE",
               "/meshes/1/primitives/0/attributes/WEIGHTS_0"},
        Expect{"image_bad_mime.gltf", "TEXTURE_INVALID_IMAGE_MIME_TYPE", "/textures/0/source"},
        // The declared length, though the importer reads the data URI's real length.
        Expect{"buffer_byte_length_mismatch.gltf", "BUFFER_BYTE_LENGTH_MISMATCH", "/buffers/0"},
        Expect{"joints_without_weights.gltf", "NODE_SKIN_WITH_NON_SKINNED_MESH", "/nodes/2"}),
    test::expect_name);

// What the specification allows loads without an error, whatever tinygltf thinks.
TEST(LoadAndWarn, IntegersWrittenAsFloatsLoad) {
    const auto r = sherpa::scene::load_scene(case_path("integer_as_float.gltf"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->validation.count(Severity::Error), 0u) << dump(r.scene->validation);
    EXPECT_EQ(r.scene->meshes.size(), 2u);
}

// A sampler value out of its list is the Khronos validator's VALUE_NOT_IN_LIST warning,
// not a reason to refuse the file: it is read as unspecified (linear or trilinear
// filtering, repeat wrapping), and the note says which.
TEST(LoadAndWarn, SamplerValueOutOfItsListIsReadAsUnspecified) {
    const auto r = sherpa::scene::load_scene(case_path("sampler_bad_filter.gltf"));
    ASSERT_TRUE(r) << r.error;
    const ValidationReport& v = r.scene->validation;
    EXPECT_TRUE(has(v, "VALUE_NOT_IN_LIST", "/samplers/0/magFilter")) << dump(v);
    bool noted = false;
    for (const auto& m : v.messages)
        noted |= m.pointer == "/samplers/0/magFilter" && m.code == "SHERPA_IMPORT_NOTE" &&
                 m.message.find("linear filtering is used") != std::string::npos;
    EXPECT_TRUE(noted) << dump(v);
    ASSERT_EQ(r.scene->samplers.size(), 1u);
    EXPECT_EQ(r.scene->samplers[0].mag_filter, sherpa::scene::Filter::Linear);
    EXPECT_EQ(r.scene->samplers[0].min_filter, sherpa::scene::Filter::Linear); // 9987: trilinear
    EXPECT_EQ(r.scene->samplers[0].mipmap_mode, sherpa::scene::MipmapMode::Linear);
}

TEST(LoadAndWarn, PlaceholderBufferWithoutUriLoadsAndNamesWhatItSkips) {
    auto doc = test::read_json(case_path("valid.gltf"));
    doc["buffers"].push_back({{"byteLength", 1024}}); // a placeholder nothing reads
    const auto path = std::filesystem::temp_directory_path() / "sherpa_placeholder_buffer.gltf";
    std::ofstream(path) << doc.dump();
    const auto r = sherpa::scene::load_scene(path.string());
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->meshes.size(), 2u);
    EXPECT_TRUE(has(r.scene->validation, "SHERPA_BUFFER_NOT_LOADED", "/buffers/1"))
        << dump(r.scene->validation);
    EXPECT_EQ(r.scene->validation.count(Severity::Error), 0u) << dump(r.scene->validation);
}

TEST(LoadAndWarn, UnfetchableUriIsAWarningAndItsReadersAreSkipped) {
    auto doc = test::read_json(case_path("valid.gltf"));
    doc["buffers"][0]["uri"] = "https://example.invalid/data.bin";
    const auto path = std::filesystem::temp_directory_path() / "sherpa_remote_buffer.gltf";
    std::ofstream(path) << doc.dump();
    const auto r = sherpa::scene::load_scene(path.string());
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(has(r.scene->validation, "NON_RELATIVE_URI", "/buffers/0/uri"));
    EXPECT_TRUE(has(r.scene->validation, "SHERPA_BUFFER_NOT_LOADED", "/buffers/0"));
    EXPECT_TRUE(r.scene->meshes.empty()) << "every primitive read the remote buffer";
    EXPECT_EQ(r.scene->primitives.size(), 2u) << "skipped primitives stay listed";
    EXPECT_FALSE(r.scene->primitives[0].skipped_reason.empty());
}

TEST(LoadAndWarn, DataUriInGlbLoads) {
    const auto r = sherpa::scene::load_scene(case_path("glb_data_uri.glb"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->meshes.size(), 2u);
}

TEST(LoadAndWarn, RepeatedKeyTimesSkipTheChannelNotTheFile) {
    const auto r = sherpa::scene::load_scene(case_path("anim_input_non_increasing.gltf"));
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->animations.size(), 1u);
    EXPECT_TRUE(r.scene->animations[0].channels.empty());
    EXPECT_EQ(r.scene->meshes.size(), 2u);
}

TEST(LoadAndWarn, RefusalCarriesTheValidatorsMessages) {
    const auto r = sherpa::scene::load_scene((test::data_dir() / "version_3.gltf").string());
    ASSERT_FALSE(r);
    ASSERT_FALSE(r.validation.messages.empty());
    EXPECT_EQ(r.validation.messages.back().code, "SHERPA_LOAD_REFUSED");
    EXPECT_EQ(r.validation.messages.back().severity, Severity::Error);
}

// A view past its buffer is still refused (the importer's raw checks), but the report
// carries the validator's message as well as the refusal.
TEST(LoadAndWarn, RefusedFileKeepsTheKhronosCode) {
    const auto r = sherpa::scene::load_scene(case_path("buffer_view_too_long.gltf"));
    ASSERT_FALSE(r);
    EXPECT_TRUE(has(r.validation, "BUFFER_VIEW_TOO_LONG", "/bufferViews/8/byteLength"))
        << dump(r.validation);
    EXPECT_TRUE(has(r.validation, "SHERPA_LOAD_REFUSED", "/bufferViews/8")) << dump(r.validation);
}

// Refusals that happen before or after the validator still carry its Khronos codes.
TEST(LoadAndWarn, RefusedFilesNameTheKhronosCodes) {
    const struct {
        const char* file;
        const char* code;
        const char* pointer;
    } cases[] = {
        {"version_3.gltf", "UNKNOWN_ASSET_MAJOR_VERSION", "/asset/version"},
        {"invalid_json.gltf", "INVALID_JSON", ""},
        {"truncated.glb", "GLB_UNEXPECTED_END_OF_CHUNK_DATA", ""},
        {"buffer_uri_parent.gltf", "IO_ERROR", "/buffers/0/uri"},
        {"view_offset_wraps.gltf", "BUFFER_VIEW_TOO_LONG", "/bufferViews/0/byteOffset"},
        {"fractional_byte_length.gltf", "ACCESSOR_TOO_LONG", "/accessors/0/byteOffset"},
    };
    for (const auto& c : cases) {
        const auto r = sherpa::scene::load_scene((test::data_dir() / c.file).string());
        const ValidationReport& report = r ? r.scene->validation : r.validation;
        EXPECT_TRUE(has(report, c.code, c.pointer)) << c.file << "\n" << dump(report);
    }
}

// No error the Khronos validator does not report: a meshopt fallback buffer has no
// data by design, and a data URI of another media type is not read by Khronos.
TEST(Validation, NoLengthMismatchForBuffersWithoutDataByDesign) {
    for (const auto& path : {test::data_dir() / "compressed_seeds" / "Box.meshopt.glb",
                             test::data_dir() / "validation" / "data_uri_mime.gltf"}) {
        const auto r = sherpa::scene::load_scene(path.string());
        const ValidationReport& report = r ? r.scene->validation : r.validation;
        for (const auto& m : report.messages)
            EXPECT_NE(m.code, "BUFFER_BYTE_LENGTH_MISMATCH") << path << "\n" << dump(report);
    }
}

TEST(Validation, ImporterWarningsBecomeMessagesWithPointers) {
    EXPECT_EQ(
        sherpa::scene::detail::pointer_of_path("meshes[0].primitives[1].attributes.POSITION: x"),
        "/meshes/0/primitives/1/attributes/POSITION");
    EXPECT_EQ(sherpa::scene::detail::pointer_of_path("animations[2]: 3 channel(s)"),
              "/animations/2");
    EXPECT_EQ(sherpa::scene::detail::pointer_of_path("attributes TEXCOORD_2 are not used"), "");
}

// The hostile reproducers: every one either loads or is refused, never crashes; a
// loaded one carries only well-formed messages.
TEST(Validation, HostileFilesGiveWellFormedReports) {
    for (const auto& e : std::filesystem::directory_iterator(test::data_dir())) {
        const auto ext = e.path().extension();
        if (ext != ".gltf" && ext != ".glb") continue;
        const auto r = sherpa::scene::load_scene(e.path().string());
        const ValidationReport& report = r ? r.scene->validation : r.validation;
        for (const auto& m : report.messages) {
            EXPECT_FALSE(m.code.empty()) << e.path();
            EXPECT_TRUE(m.pointer.empty() || m.pointer[0] == '/') << e.path() << " " << m.pointer;
        }
        if (!r) {
            EXPECT_FALSE(r.error.empty()) << e.path();
        }
    }
}

} // namespace
