#pragma once
// JSON pointers (RFC 6901) of a glTF file resolved to the objects of the loaded
// Scene: what a validation message names, as something an inspector can select.
// Pure functions over the Scene.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/scene/validation.h>

namespace sherpa::scene {

struct Scene;

enum class TargetKind : std::uint8_t {
    None, // the pointer names nothing this scene has (or is malformed)
    Asset,
    Scene,
    Node,
    Mesh,
    Primitive,
    Material,
    Texture,
    Image,
    Sampler,
    Accessor,
    BufferView,
    Buffer,
    Animation,
    AnimationChannel,
    AnimationSampler,
    Skin,
    SkinJoint,
    Camera,
    Light,
    Extension, // a name of extensionsUsed / extensionsRequired
};
std::string_view to_string(TargetKind kind);

// An engine mesh that reads an accessor, and as what ("POSITION", "indices").
struct AccessorUse {
    std::int32_t engine_mesh = -1;
    std::string attribute;
};

// The object a pointer names, with what the editor needs to select and show it;
// -1 where a field does not apply or the scene has no such thing.
struct PointerTarget {
    TargetKind kind = TargetKind::None;
    std::int32_t index = -1;       // in the file's array of that kind (nodes, materials, ...)
    std::int32_t sub = -1;         // primitive of a mesh, channel/sampler of an animation, joint
    std::int32_t node = -1;        // Scene::nodes: the node, joint, channel target, or a node
                                   // that places the mesh, primitive, camera or light
    std::int32_t engine_mesh = -1; // Scene::meshes: the primitive, or first user
    std::int32_t material = -1;    // Scene::materials
    std::int32_t texture = -1;     // Scene::textures (an image: the first texture of it)
    std::int32_t image = -1;       // Scene::images
    std::vector<AccessorUse> uses; // an accessor's readers among the engine meshes
    std::string rest;              // the pointer below the object ("/min/0")
};

// One RFC 6901 reference token: '~' written "~0" and '/' written "~1", so that a
// name ("KHR_materials_clearcoat", an attribute, a JSON key) is one pointer step.
std::string json_pointer_token(std::string_view name);

// Resolves `pointer` ("/meshes/0/primitives/1/attributes/POSITION"). Never throws;
// a malformed pointer or an index the scene lacks gives TargetKind::None.
PointerTarget resolve_pointer(const Scene& scene, std::string_view pointer);

// The worst severity of the messages about each object, for markers: -1 where none,
// else the Severity's value (Error 0 is the worst). A message marks what it resolves
// to: a primitive (and an accessor's message every primitive that reads it), a
// material, a texture (an image's message every texture of it), an animation (and
// a channel's target node), a skin (and a joint's node), a node.
struct ObjectMarks {
    std::vector<int> nodes;         // per Scene::nodes
    std::vector<int> engine_meshes; // per Scene::meshes
    std::vector<int> materials;     // per Scene::materials
    std::vector<int> textures;      // per Scene::textures
    std::vector<int> animations;    // per Scene::animations
    std::vector<int> skins;         // per Scene::skins
};
ObjectMarks mark_objects(const Scene& scene, const std::vector<ValidationMessage>& messages);

// The element index a message names in its text ("... element at index 12 ..."), as
// the Khronos validator writes data errors; -1 when it names none.
std::int64_t element_index_in_message(std::string_view message);

} // namespace sherpa::scene
