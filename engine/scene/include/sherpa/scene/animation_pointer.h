#pragma once
// KHR_animation_pointer: animation channels that target a property by JSON pointer
// (material factors, texture transforms, light and camera properties, node
// visibility). The importer resolves each pointer once into a AnimatedTarget; a pointer
// that names an unsupported or invalid target is a warning naming the channel's JSON
// pointer, and the channel is skipped. Evaluation samples them with the same
// sample_animation() as node channels (glTF's STEP, LINEAR, CUBICSPLINE) into
// AnimatedProperty values that apply_animated_properties() writes into copies of the
// scene's materials, lights, cameras and visibility: what the renderer draws per frame.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::scene {

struct Scene;
struct MaterialInstance;
struct Light;
struct Camera;

enum class PointerProperty : std::uint8_t {
    // materials[object]
    BaseColorFactor,     // vec4
    EmissiveFactor,      // vec3
    MetallicFactor,      // float
    RoughnessFactor,     // float
    AlphaCutoff,         // float
    NormalScale,         // float
    OcclusionStrength,   // float
    EmissiveStrength,    // KHR_materials_emissive_strength
    Ior,                 // KHR_materials_ior
    SpecularFactor,      // KHR_materials_specular
    SpecularColorFactor, // KHR_materials_specular, vec3
    ClearcoatFactor,     // KHR_materials_clearcoat
    ClearcoatRoughnessFactor,
    ClearcoatNormalScale,           // clearcoatNormalTexture/scale
    TransmissionFactor,             // KHR_materials_transmission
    ThicknessFactor,                // KHR_materials_volume
    AttenuationDistance,            //
    AttenuationColor,               // vec3
    SheenColorFactor,               // KHR_materials_sheen, vec3
    SheenRoughnessFactor,           //
    IridescenceFactor,              // KHR_materials_iridescence
    IridescenceIor,                 //
    IridescenceThicknessMinimum,    // nm
    IridescenceThicknessMaximum,    // nm
    AnisotropyStrength,             // KHR_materials_anisotropy
    AnisotropyRotation,             // radians
    Dispersion,                     // KHR_materials_dispersion
    DiffuseTransmissionFactor,      // KHR_materials_diffuse_transmission
    DiffuseTransmissionColorFactor, // vec3
    TextureOffset,                  // KHR_texture_transform of texture slot `slot`, vec2
    TextureRotation,                // float
    TextureScale,                   // vec2
    // extensions.KHR_lights_punctual.lights[object]
    LightColor,     // vec3
    LightIntensity, // float
    LightRange,     // float
    SpotInnerCone,  // float
    SpotOuterCone,  // float
    // cameras[object]
    CameraYfov,
    CameraAspect,
    CameraZnear, // perspective/znear
    CameraZfar,  // perspective/zfar
    // orthographic/znear, zfar: the same camera fields, their own pointers
    CameraOrthographicZnear,
    CameraOrthographicZfar,
    CameraXmag,
    CameraYmag,
    // nodes[object].extensions.KHR_node_visibility.visible (bool: value != 0, stepped)
    NodeVisible,
};
std::string_view to_string(PointerProperty p);

// Texture slots a KHR_texture_transform pointer can name: the core ones, then the
// ratified material extensions' (each only where the material draws that extension).
enum class PointerTextureSlot : std::uint8_t {
    BaseColor,
    MetallicRoughness,
    Normal,
    Occlusion,
    Emissive,
    Specular,
    SpecularColor,
    Clearcoat,
    ClearcoatRoughness,
    ClearcoatNormal,
    SheenColor,
    SheenRoughness,
    Transmission,
    Thickness,
    DiffuseTransmission,
    DiffuseTransmissionColor,
    Anisotropy,
    Iridescence,
    IridescenceThickness,
};

// Floats one value of `p` has (1..4).
std::uint32_t pointer_width(PointerProperty p);

struct AnimatedTarget {
    PointerProperty property = PointerProperty::BaseColorFactor;
    std::uint32_t object = 0; // material, light, camera or node index (the file's)
    PointerTextureSlot slot = PointerTextureSlot::BaseColor;
};

// One KHR_animation_pointer channel as the importer keeps it.
struct PointerChannel {
    std::uint32_t sampler = 0; // into Animation::samplers
    AnimatedTarget target;
    std::string pointer;                          // as written in the file
    std::uint32_t source = 0, source_sampler = 0; // the file's indices (for JSON pointers)
};

// Why `pointer` cannot be animated in `scene` (empty: it can, `out` set). Node TRS and
// weights pointers are not resolved here (the importer makes node channels of them).
std::string resolve_animation_pointer(const Scene& scene, std::string_view pointer,
                                      AnimatedTarget& out);

// One property's value at a time.
struct AnimatedProperty {
    AnimatedTarget target;
    float value[4] = {0, 0, 0, 0}; // pointer_width(target.property) floats
};

// Values of animation `animation`'s pointer channels at `time` (none for -1), in
// channel order (a later channel on the same target wins when applied).
std::vector<AnimatedProperty> evaluate_pointer_channels(const Scene& scene, std::int32_t animation,
                                                        double time);

// The JSON pointer of a target, as the Object Model writes it
// ("/materials/0/pbrMetallicRoughness/baseColorFactor").
std::string pointer_of(const AnimatedTarget& target);

// Writes `values` into `materials`, `lights`, `cameras` (copies of the scene's) and
// `visible` (per node; true where not hidden). Returns the materials it changed
// (ascending, once each). Targets past a span's end are ignored.
std::vector<std::uint32_t> apply_animated_properties(std::span<const AnimatedProperty> values,
                                                     std::span<MaterialInstance> materials,
                                                     std::span<Light> lights,
                                                     std::span<Camera> cameras,
                                                     std::vector<bool>* visible);

} // namespace sherpa::scene
