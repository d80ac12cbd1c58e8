// The validator where the Khronos glTF-Validator's answer depends on more than one
// property at a time: document order, extension values, sparse and image data, and
// primitives the importer skips while the rest of the file loads. The Khronos verdict
// on each generated case is checked by validation_oracle_agreement; these pin the
// pointers and what loads.
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "gltf_validate.h" // engine/scene/src: parse_gltf_document, DocumentOrder

namespace {

namespace test = sherpa::test;
using sherpa::Severity;
using sherpa::ValidationReport;

std::string case_path(const std::string& name) {
    return (test::data_dir() / "validation" / name).string();
}

bool has(const ValidationReport& r, const std::string& code, const std::string& pointer) {
    for (const auto& m : r.messages)
        if (m.code == code && m.pointer == pointer) return true;
    return false;
}

std::string dump(const ValidationReport& r) {
    std::string s;
    for (const auto& m : r.messages) s += m.code + " " + m.pointer + ": " + m.message + "\n";
    return s;
}

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
    sherpa::detail::DocumentOrder order;
    ASSERT_EQ(sherpa::detail::parse_gltf_document(bytes_of(text), root, nullptr, &order), "");
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
    const auto r = sherpa::load_scene(case_path("attributes_share_view.gltf"));
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(has(r.scene->validation, "MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE",
                    "/meshes/0/primitives/0/attributes/NORMAL"))
        << dump(r.scene->validation);
    EXPECT_FALSE(has(r.scene->validation, "MESH_PRIMITIVE_ACCESSOR_WITHOUT_BYTESTRIDE",
                     "/meshes/0/primitives/0/attributes/POSITION"))
        << dump(r.scene->validation);
}

} // namespace
