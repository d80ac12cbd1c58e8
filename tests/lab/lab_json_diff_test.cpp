// json_diff() on hand-made edits of a real asset (BoxTextured): every edit is found
// at its JSON pointer, min/max drift is measured by use, and nothing else is reported.
#include <sherpa/lab/json_diff.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;
using namespace sherpa::lab;

const std::string kBox = std::string(SHERPA_ASSETS_DIR) + "/gltf/BoxTextured/glTF/BoxTextured.gltf";

json box() {
    std::ifstream f(kBox);
    return json::parse(f);
}

const JsonChange* find(const JsonDiff& d, const std::string& pointer) {
    for (const JsonChange& c : d.changes)
        if (c.pointer == pointer) return &c;
    return nullptr;
}

TEST(JsonDiff, IdenticalFilesDifferInNothing) {
    const std::string text = box().dump();
    const JsonDiff d = json_diff(text, box().dump(2)); // formatting is not a difference
    EXPECT_TRUE(d.error.empty());
    EXPECT_TRUE(d.changes.empty());
    EXPECT_TRUE(d.drift.empty());
    EXPECT_EQ(d.objects_a, d.objects_b);
    EXPECT_EQ(d.unchanged, d.objects_a);
}

TEST(JsonDiff, FieldEditsAdditionsAndRemovalsByPointer) {
    json b = box();
    b["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.5;
    b["materials"][0]["doubleSided"] = true;
    b["nodes"].push_back({{"name", "extra"}});
    b["samplers"] = json::array(); // removed (BoxTextured has one)
    b["extensionsUsed"] = {"KHR_materials_clearcoat"};
    b["asset"]["generator"] = "hand edit";
    const JsonDiff d = json_diff(box().dump(), b.dump());
    ASSERT_TRUE(d.error.empty()) << d.error;
    const JsonChange* material = find(d, "/materials/0");
    ASSERT_TRUE(material);
    EXPECT_EQ(material->kind, JsonChangeKind::Changed);
    EXPECT_EQ(material->fields,
              (std::vector<std::string>{"/doubleSided: added true",
                                        "/pbrMetallicRoughness/metallicFactor: 0.0 -> 0.5"}));
    const JsonChange* node = find(d, "/nodes/2");
    ASSERT_TRUE(node);
    EXPECT_EQ(node->kind, JsonChangeKind::Added);
    const JsonChange* sampler = find(d, "/samplers/0");
    ASSERT_TRUE(sampler);
    EXPECT_EQ(sampler->kind, JsonChangeKind::Removed);
    const JsonChange* used = find(d, "/extensionsUsed");
    ASSERT_TRUE(used);
    EXPECT_EQ(used->kind, JsonChangeKind::Added);
    const JsonChange* asset = find(d, "/asset");
    ASSERT_TRUE(asset);
    ASSERT_EQ(asset->fields.size(), 1u);
    EXPECT_EQ(asset->fields[0].rfind("/generator: ", 0), 0u) << asset->fields[0];
    EXPECT_EQ(d.changes.size(), 5u) << "nothing else differs";
}

TEST(JsonDiff, AccessorMinMaxDriftByUse) {
    json b = box();
    b["accessors"][2]["max"][0] = 0.75; // POSITION: max x 0.5 -> 0.75
    const JsonDiff d = json_diff(box().dump(), b.dump());
    ASSERT_EQ(d.drift.size(), 1u);
    const AccessorDrift& drift = d.drift[0];
    EXPECT_EQ(drift.use, "/meshes/0/primitives/0/attributes/POSITION");
    EXPECT_EQ(drift.accessor_a, 2);
    EXPECT_EQ(drift.accessor_b, 2);
    EXPECT_TRUE(drift.comparable);
    EXPECT_DOUBLE_EQ(drift.drift, 0.25);
    EXPECT_DOUBLE_EQ(drift.relative, 0.25); // of the extent 1
    const JsonChange* accessor = find(d, "/accessors/2");
    ASSERT_TRUE(accessor);
    EXPECT_EQ(accessor->fields, std::vector<std::string>{"/max: [0.5,0.5,0.5] -> [0.75,0.5,0.5]"});
}

// Optimizers renumber accessors: the drift follows the use, not the index.
TEST(JsonDiff, DriftFollowsRenumberedAccessors) {
    json b = box();
    b["accessors"].push_back(b["accessors"][2]);
    b["accessors"][4]["min"][2] = -0.5 - 1e-3;
    b["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 4;
    const JsonDiff d = json_diff(box().dump(), b.dump());
    ASSERT_EQ(d.drift.size(), 1u);
    EXPECT_EQ(d.drift[0].accessor_b, 4);
    EXPECT_NEAR(d.drift[0].drift, 1e-3, 1e-12);
}

// Normalized integers compare in their float values; plain integers standing for
// floats (quantized, dequantized by a node transform) are another space.
TEST(JsonDiff, QuantizedAccessorsAreComparedOnlyInOneValueSpace) {
    json b = box();
    json& uv = b["accessors"][3]; // TEXCOORD_0: min [0,0] max [6,1]
    uv["componentType"] = 5123;
    uv["normalized"] = true;
    uv["min"] = {0, 0};
    uv["max"] = {65535, 65535};
    JsonDiff d = json_diff(box().dump(), b.dump());
    ASSERT_EQ(d.drift.size(), 1u);
    EXPECT_TRUE(d.drift[0].comparable) << d.drift[0].note;
    EXPECT_DOUBLE_EQ(d.drift[0].drift, 5.0); // max u: 6 -> 1
    EXPECT_NE(d.drift[0].note.find("FLOAT -> UNSIGNED_SHORT normalized"), std::string::npos);

    json& position = b["accessors"][2];
    position["componentType"] = 5123;
    position["min"] = {0, 0, 0};
    position["max"] = {16383, 16383, 16383};
    d = json_diff(box().dump(), b.dump());
    ASSERT_EQ(d.drift.size(), 2u);
    const AccessorDrift& p = d.drift[0].use.ends_with("POSITION") ? d.drift[0] : d.drift[1];
    EXPECT_FALSE(p.comparable);
    EXPECT_NE(p.note.find("different value spaces"), std::string::npos) << p.note;
}

TEST(JsonDiff, BadDocumentsAreErrorsNotThrows) {
    EXPECT_FALSE(json_diff("{", "{}").error.empty());
    EXPECT_FALSE(json_diff("{}", "[1]").error.empty());
    // Wrongly typed glTF members are diffed as values, not trusted as structure.
    const JsonDiff d = json_diff(R"({"meshes":[{"primitives":7}],"accessors":{}})",
                                 R"({"meshes":"x","accessors":[{"min":"a"}]})");
    EXPECT_TRUE(d.error.empty());
    EXPECT_FALSE(d.changes.empty());
}

TEST(JsonDiff, ReadsTheJsonChunkOfAGlb) {
    const std::string text = R"({"asset":{"version":"2.0"}})";
    std::string padded = text;
    while (padded.size() % 4) padded += ' ';
    auto le32 = [](std::string& out, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out += static_cast<char>(v >> (8 * i));
    };
    std::string glb = "glTF";
    le32(glb, 2);
    le32(glb, static_cast<std::uint32_t>(20 + padded.size()));
    le32(glb, static_cast<std::uint32_t>(padded.size()));
    glb += "JSON" + padded;
    const auto path = std::filesystem::temp_directory_path() / "sherpa_json_diff_test.glb";
    std::ofstream(path, std::ios::binary) << glb;
    std::string out, error;
    ASSERT_TRUE(read_gltf_json(path.string(), out, error)) << error;
    EXPECT_EQ(out, padded);
    // A chunk longer than the file is refused, naming the file.
    std::ofstream(path, std::ios::binary) << glb.substr(0, glb.size() - 4);
    EXPECT_FALSE(read_gltf_json(path.string(), out, error));
    EXPECT_NE(error.find(path.string()), std::string::npos) << error;
    std::filesystem::remove(path);
}

} // namespace
