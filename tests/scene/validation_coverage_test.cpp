// The validator where the Khronos glTF-Validator's answer depends on more than one
// property at a time: document order, extension values, sparse and image data, and
// primitives the importer skips while the rest of the file loads. The Khronos verdict
// on each generated case is checked by validation_oracle_agreement; these pin the
// pointers and what loads.
#include "validation_checks.h"

#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "gltf_validate.h" // engine/scene/src: parse_gltf_document, DocumentOrder

namespace {

namespace test = sherpa::test;
using sherpa::scene::Severity;
using sherpa::scene::ValidationReport;

using test::case_path;
using test::dump;
using test::Expect;
using test::has;

std::span<const std::uint8_t> bytes_of(const std::string& s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// The one parse keeps the attribute names of each primitive as written; the JSON value
// itself keeps them sorted.
TEST(DocumentOrder, ParseRecordsAttributeNamesAsWritten) {
    const std::string text = R"({"asset":{"version":"2.0"},"meshes":[
        {"primitives":[{"attributes":{"TEXCOORD_0":2,"POSITION":0,"NORMAL":1}},
                       {"indices":0,"attributes":{"POSITION":0}}]},
        {"name":"attributes","primitives":[]},
        {"primitives":[{"extras":{"attributes":{"Z":1,"A":2}},"attributes":{"b":1,"a":2,"b":3}}]}],
        "attributes":{"NOT":1}})";
    nlohmann::json root;
    sherpa::scene::detail::DocumentOrder order;
    ASSERT_EQ(sherpa::scene::detail::parse_gltf_document(bytes_of(text), root, nullptr, &order),
              "");
    using Names = std::vector<std::string>;
    ASSERT_NE(order.attributes_of(0, 0), nullptr);
    EXPECT_EQ(*order.attributes_of(0, 0), (Names{"TEXCOORD_0", "POSITION", "NORMAL"}));
    EXPECT_EQ(*order.attributes_of(0, 1), (Names{"POSITION"}));
    EXPECT_EQ(order.attributes_of(1, 0), nullptr);
    // Only /meshes/m/primitives/p/attributes counts (not extras' look-alike); a
    // repeated key is listed at each place it is written.
    EXPECT_EQ(*order.attributes_of(2, 0), (Names{"b", "a", "b"}));
    EXPECT_EQ(root["meshes"][0]["primitives"][0]["attributes"].begin().key(), "NORMAL");
}

// POSITION and NORMAL read one view without byteStride: the Khronos validator names
// the second attribute in document order (NORMAL), which sorted order would not.
TEST(DocumentOrder, SharedViewNamesTheSecondAttributeAsWritten) {
    const auto r = sherpa::scene::load_scene(case_path("attributes_share_view.gltf"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(has(r.scene->validation, "MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE",
                    "/meshes/0/primitives/0/attributes/NORMAL"))
        << dump(r.scene->validation);
    EXPECT_FALSE(has(r.scene->validation, "MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE",
                     "/meshes/0/primitives/0/attributes/POSITION"))
        << dump(r.scene->validation);
}

// Material extension values: the Khronos validator's codes where it knows the
// extension, SHERPA_ codes where it does not (KHR_materials_diffuse_transmission); the
// files load either way.
class LoadsAndNames : public ::testing::TestWithParam<Expect> {};

TEST_P(LoadsAndNames, TheCodeAtItsPointer) {
    const auto r = sherpa::scene::load_scene(case_path(GetParam().file));
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(has(r.scene->validation, GetParam().code, GetParam().pointer))
        << dump(r.scene->validation);
}

#define EXT "/materials/0/extensions/"
INSTANTIATE_TEST_SUITE_P(
    MaterialExtension, LoadsAndNames,
    ::testing::Values(
        Expect{"ext_ior_range.gltf", "VALUE_NOT_IN_RANGE", EXT "KHR_materials_ior/ior"},
        Expect{"ext_ior_type.gltf", "TYPE_MISMATCH", EXT "KHR_materials_ior/ior"},
        Expect{"ext_specular_range.gltf", "VALUE_NOT_IN_RANGE",
               EXT "KHR_materials_specular/specularColorFactor/0"},
        Expect{"ext_specular_texture.gltf", "UNRESOLVED_REFERENCE",
               EXT "KHR_materials_specular/specularTexture/index"},
        Expect{"ext_volume_range.gltf", "VALUE_NOT_IN_RANGE",
               EXT "KHR_materials_volume/attenuationDistance"},
        Expect{"ext_volume_no_transmission.gltf", "KHR_MATERIALS_VOLUME_NO_TRANSMISSION",
               EXT "KHR_materials_volume"},
        Expect{"ext_volume_no_transmission.gltf", "KHR_MATERIALS_VOLUME_DOUBLE_SIDED",
               EXT "KHR_materials_volume"},
        Expect{"ext_dispersion_range.gltf", "KHR_MATERIALS_DISPERSION_NO_VOLUME",
               EXT "KHR_materials_dispersion"},
        Expect{"ext_clearcoat_texcoord.gltf",
               "KHR_MATERIALS_CLEARCOAT_CLEARCOAT_NORMAL_TEXTURE_TEXCOORD",
               EXT "KHR_materials_clearcoat/clearcoatNormalTexture"},
        Expect{"ext_no_tangent_space.gltf", "MESH_PRIMITIVE_NO_TANGENT_SPACE",
               "/meshes/0/primitives/0/material"},
        Expect{"ext_iridescence_texture_unused.gltf",
               "KHR_MATERIALS_IRIDESCENCE_THICKNESS_TEXTURE_UNUSED",
               EXT "KHR_materials_iridescence/iridescenceThicknessTexture"},
        Expect{"ext_unlit_with_others.gltf", "MULTIPLE_EXTENSIONS", EXT "KHR_materials_unlit"},
        Expect{"ext_unexpected_property.gltf", "UNEXPECTED_PROPERTY",
               EXT "KHR_materials_volume/thickness"},
        Expect{"ext_diffuse_transmission_range.gltf", "SHERPA_VALUE_NOT_IN_RANGE",
               EXT "KHR_materials_diffuse_transmission/diffuseTransmissionFactor"},
        Expect{"ext_diffuse_transmission_range.gltf", "SHERPA_VALUE_NOT_IN_RANGE",
               EXT "KHR_materials_diffuse_transmission/diffuseTransmissionColorFactor/1"}),
    test::expect_name);
#undef EXT

// Sparse accessors are read with their overrides applied, after their indices are
// checked; a matrix whose last row is not (0, 0, 0, 1) is named; image bytes are
// checked by their headers.
INSTANTIATE_TEST_SUITE_P(
    DataChecks, LoadsAndNames,
    ::testing::Values(
        Expect{"sparse_indices_non_increasing.gltf", "ACCESSOR_SPARSE_INDICES_NON_INCREASING",
               "/accessors/1/sparse"},
        Expect{"sparse_index_oob.gltf", "ACCESSOR_SPARSE_INDEX_OOB", "/accessors/1/sparse"},
        Expect{"sparse_value_non_unit.gltf", "ACCESSOR_VECTOR3_NON_UNIT",
               "/meshes/0/primitives/0/attributes/NORMAL"},
        Expect{"sparse_max_mismatch.gltf", "ACCESSOR_MAX_MISMATCH", "/accessors/0/max/0"},
        Expect{"sparse_max_mismatch.gltf", "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND",
               "/accessors/0/max/0"},
        Expect{"sparse_count.gltf", "ACCESSOR_TOO_LONG", "/accessors/2/sparse/indices"},
        Expect{"ibm_invalid.gltf", "ACCESSOR_INVALID_IBM", "/skins/0/inverseBindMatrices"},
        // Image headers (no pixel decoded): format, media type, cut streams, size.
        Expect{"image_unrecognized.gltf", "IMAGE_UNRECOGNIZED_FORMAT", "/images/0"},
        Expect{"image_mime_mismatch.gltf", "IMAGE_MIME_TYPE_INVALID", "/images/0/bufferView"},
        Expect{"image_truncated.gltf", "IMAGE_UNEXPECTED_EOS", "/images/0"},
        Expect{"image_npot.gltf", "IMAGE_NPOT_DIMENSIONS", "/images/0"},
        Expect{"image_features.gltf", "IMAGE_FEATURES_UNSUPPORTED", "/images/0"}),
    test::expect_name);

// Data the Khronos validator reads that Sherpa used to leave alone: an infinite value
// is outside the declared bounds as well as not finite, and index data past its view
// is read where the buffer holds it.
TEST(DataChecks, InfinityIsOutOfBoundsAndIndicesPastTheirViewAreRead) {
    auto r = sherpa::scene::load_scene((test::data_dir() / "inf_position.gltf").string());
    ValidationReport report = r ? r.scene->validation : r.validation;
    EXPECT_TRUE(has(report, "ACCESSOR_INVALID_FLOAT", "/accessors/0")) << dump(report);
    EXPECT_TRUE(has(report, "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND", "/accessors/0/max/1"))
        << dump(report);
    r = sherpa::scene::load_scene((test::data_dir() / "accessor_out_of_range.gltf").string());
    report = r ? r.scene->validation : r.validation;
    EXPECT_TRUE(has(report, "ACCESSOR_INDEX_OOB", "/meshes/0/primitives/0/indices"))
        << dump(report);
}

// A valid sparse accessor (an override inside the declared bounds) gives no error:
// reading the overrides adds no false message.
TEST(DataChecks, ValidSparseAccessorHasNoDataErrors) {
    const auto r = sherpa::scene::load_scene(case_path("sparse_valid.gltf"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->validation.count(Severity::Error), 0u) << dump(r.scene->validation);
}

// An extension object is read only where extensionsUsed declares it (the Khronos
// validator stops at UNDECLARED_EXTENSION), and 0 is a valid ior (the value in [1, inf)
// or exactly 0).
TEST(MaterialExtension, UndeclaredIsNotReadAndIorZeroIsValid) {
    auto doc = test::read_json(case_path("ext_ior_range.gltf"));
    doc.erase("extensionsUsed");
    auto path = std::filesystem::temp_directory_path() / "sherpa_ext_undeclared.gltf";
    std::ofstream(path) << doc.dump();
    auto r = sherpa::scene::load_scene(path.string());
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(has(r.scene->validation, "UNDECLARED_EXTENSION",
                    "/materials/0/extensions/KHR_materials_ior"));
    EXPECT_FALSE(has(r.scene->validation, "VALUE_NOT_IN_RANGE",
                     "/materials/0/extensions/KHR_materials_ior/ior"));
    doc = test::read_json(case_path("ext_ior_range.gltf"));
    doc["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 0;
    path = std::filesystem::temp_directory_path() / "sherpa_ext_ior_zero.gltf";
    std::ofstream(path) << doc.dump();
    r = sherpa::scene::load_scene(path.string());
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->validation.count(Severity::Error), 0u) << dump(r.scene->validation);
}

} // namespace
