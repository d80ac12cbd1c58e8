// resolve_pointer() and mark_objects() on real assets: every kind of object a
// validation message can name lands on the Scene object the editor selects.
#include "load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/pointer_target.h>
#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

namespace {

using sherpa::scene::PointerTarget;
using sherpa::scene::resolve_pointer;
using sherpa::scene::Severity;
using sherpa::scene::TargetKind;

TEST(PointerTarget, NodesMeshesPrimitivesAndAccessorsOfASkinnedFile) {
    const auto scene = sherpa::test::load_scene_or_fail(sherpa::test::gltf_asset("RiggedSimple"));
    ASSERT_TRUE(scene);
    const PointerTarget node = resolve_pointer(*scene, "/nodes/1");
    EXPECT_EQ(node.kind, TargetKind::Node);
    EXPECT_EQ(node.node, 1);

    // The file's mesh 0 primitive 0 is placed by node 1.
    const PointerTarget prim =
        resolve_pointer(*scene, "/meshes/0/primitives/0/attributes/JOINTS_0");
    EXPECT_EQ(prim.kind, TargetKind::Primitive);
    EXPECT_EQ(prim.index, 0);
    EXPECT_EQ(prim.sub, 0);
    EXPECT_EQ(prim.engine_mesh, scene->mesh_primitives[0][0]);
    EXPECT_EQ(prim.node, 1);
    EXPECT_EQ(prim.rest, "/attributes/JOINTS_0");

    // Accessor 3 is POSITION, 0 the indices: the rows of that primitive.
    const PointerTarget position = resolve_pointer(*scene, "/accessors/3/max/0");
    EXPECT_EQ(position.kind, TargetKind::Accessor);
    ASSERT_EQ(position.uses.size(), 1u);
    EXPECT_EQ(position.uses[0].attribute, "POSITION");
    EXPECT_EQ(position.engine_mesh, prim.engine_mesh);
    EXPECT_EQ(position.node, 1);
    EXPECT_EQ(position.rest, "/max/0");
    const PointerTarget indices = resolve_pointer(*scene, "/accessors/0");
    ASSERT_EQ(indices.uses.size(), 1u);
    EXPECT_EQ(indices.uses[0].attribute, "indices");

    // Skin joint 1 is node 3; channel 4 targets node 3 (rotation).
    const PointerTarget joint = resolve_pointer(*scene, "/skins/0/joints/1");
    EXPECT_EQ(joint.kind, TargetKind::SkinJoint);
    EXPECT_EQ(joint.node, 3);
    EXPECT_EQ(resolve_pointer(*scene, "/skins/0").kind, TargetKind::Skin);
    const PointerTarget channel = resolve_pointer(*scene, "/animations/0/channels/4/target/path");
    EXPECT_EQ(channel.kind, TargetKind::AnimationChannel);
    EXPECT_EQ(channel.node, 3);
    EXPECT_EQ(scene->animations[0].channels[static_cast<std::size_t>(channel.sub)].path,
              sherpa::scene::AnimationPath::Rotation);
    EXPECT_EQ(resolve_pointer(*scene, "/animations/0/samplers/0").kind,
              TargetKind::AnimationSampler);
}

TEST(PointerTarget, MaterialsTexturesImagesAndCameras) {
    const auto box = sherpa::test::load_scene_or_fail(sherpa::test::gltf_asset("BoxTextured"));
    ASSERT_TRUE(box);
    const PointerTarget material =
        resolve_pointer(*box, "/materials/0/pbrMetallicRoughness/baseColorTexture");
    EXPECT_EQ(material.kind, TargetKind::Material);
    EXPECT_EQ(material.material, 0);
    EXPECT_EQ(material.engine_mesh, box->mesh_primitives[0][0]) << "a primitive that shows it";
    EXPECT_EQ(material.node, 1);
    const PointerTarget image = resolve_pointer(*box, "/images/0");
    EXPECT_EQ(image.kind, TargetKind::Image);
    EXPECT_EQ(image.texture, 0);
    EXPECT_EQ(resolve_pointer(*box, "/textures/0").image, 0);

    const auto cameras = sherpa::test::load_scene_or_fail(sherpa::test::gltf_asset("Cameras"));
    ASSERT_TRUE(cameras);
    const PointerTarget camera = resolve_pointer(*cameras, "/cameras/1/perspective/yfov");
    EXPECT_EQ(camera.kind, TargetKind::Camera);
    EXPECT_EQ(camera.node, 2);
}

TEST(PointerTarget, LightsAndExtensionNames) {
    const auto scene = sherpa::test::load_scene_or_fail(
        (sherpa::test::data_dir() / "lights_and_extensions.gltf").string());
    ASSERT_TRUE(scene);
    const PointerTarget light = resolve_pointer(*scene, "/extensions/KHR_lights_punctual/lights/1");
    EXPECT_EQ(light.kind, TargetKind::Light);
    EXPECT_EQ(light.node, 2);
    const auto glass = sherpa::test::load_scene_or_fail(
        (sherpa::test::data_dir() / "unsupported_material_extensions.gltf").string());
    ASSERT_TRUE(glass);
    const PointerTarget used = resolve_pointer(*glass, "/extensionsUsed/1");
    EXPECT_EQ(used.kind, TargetKind::Extension);
    EXPECT_EQ(used.material, 0) << "ADOBE_materials_thin_transparency: the Glass material";
    EXPECT_EQ(sherpa::scene::json_pointer_token("a/b~c"), "a~1b~0c");
    // "~1" is an escaped '/' (RFC 6901): the token is a name, not two tokens.
    EXPECT_EQ(resolve_pointer(*glass, "/materials/0/extensions/A~1B").rest, "/extensions/A~1B");
}

// Malformed pointers and indices the scene lacks name nothing; nothing throws.
TEST(PointerTarget, BadPointersResolveToNone) {
    const auto scene = sherpa::test::load_scene_or_fail(sherpa::test::gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    for (const char* p : {"/nodes/99", "/nodes/-1", "/nodes/01", "/nodes/x", "/nodes", "nodes/0",
                          "/materials/1", "/~2", "/skins/0", "/animations/0", "/unknown/0",
                          "/nodes/99999999999999", "/extensionsUsed/0"})
        EXPECT_EQ(resolve_pointer(*scene, p).kind, TargetKind::None) << p;
    // A primitive index past the mesh still names the mesh.
    EXPECT_EQ(resolve_pointer(*scene, "/meshes/0/primitives/7").kind, TargetKind::Mesh);
    EXPECT_EQ(resolve_pointer(*scene, "").kind, TargetKind::None);
}

TEST(PointerTarget, MarksCarryTheWorstSeverityPerObject) {
    const auto scene = sherpa::test::load_scene_or_fail(sherpa::test::gltf_asset("RiggedSimple"));
    ASSERT_TRUE(scene);
    const std::vector<sherpa::scene::ValidationMessage> messages = {
        {"ACCESSOR_MAX_MISMATCH", "", "/accessors/3/max/0", Severity::Error},
        {"NODE_EMPTY", "", "/nodes/4", Severity::Information},
        {"X", "", "/nodes/4", Severity::Hint},
        {"X", "", "/skins/0/joints/0", Severity::Warning},
        {"X", "", "/animations/0/channels/3", Severity::Information},
        {"X", "", "/nodes/99", Severity::Error}, // names nothing: marks nothing
    };
    const sherpa::scene::ObjectMarks marks = sherpa::scene::mark_objects(*scene, messages);
    const std::size_t mesh = static_cast<std::size_t>(scene->mesh_primitives[0][0]);
    EXPECT_EQ(marks.engine_meshes[mesh], int(Severity::Error));
    EXPECT_EQ(marks.nodes[4], int(Severity::Information));
    EXPECT_EQ(marks.nodes[2], int(Severity::Warning)) << "joint 0 is node 2";
    EXPECT_EQ(marks.nodes[3], int(Severity::Information)) << "channel 3 targets node 3";
    EXPECT_EQ(marks.skins[0], int(Severity::Warning));
    EXPECT_EQ(marks.animations[0], int(Severity::Information));
    EXPECT_EQ(marks.nodes[0], -1);
    EXPECT_EQ(marks.nodes[1], -1);
}

TEST(PointerTarget, ElementIndexFromKhronosMessages) {
    EXPECT_EQ(sherpa::scene::element_index_in_message(
                  "Indices accessor element at index 5 has vertex index 10 that exceeds"),
              5);
    EXPECT_EQ(sherpa::scene::element_index_in_message("Accessor element at index `12` is NaN"), 12);
    EXPECT_EQ(sherpa::scene::element_index_in_message("Accessor contains 3 element(s) greater"),
              -1);
    EXPECT_EQ(sherpa::scene::element_index_in_message("at index "), -1);
}

} // namespace
