#pragma once
// Records of glTF textures, images and samplers, before any decoding.
#include <cstdint>
#include <string>
#include <vector>

namespace sherpa::scene {

// Roles a texture is used in by some material; decides format and colour space.
enum TextureRole : std::uint8_t {
    kRoleNone = 0,
    kRoleColor = 1 << 0,  // base colour, emissive: sRGB
    kRoleLinear = 1 << 1, // metallic-roughness, occlusion: linear data
    kRoleNormal = 1 << 2, // normal map
};

enum class Filter : std::uint8_t { Nearest, Linear };
enum class MipmapMode : std::uint8_t { Nearest, Linear };
enum class AddressMode : std::uint8_t { Repeat, MirroredRepeat, ClampToEdge };

// Engine-side sampler description; the GPU layer maps it to VkSamplerCreateInfo.
struct SamplerDesc {
    Filter mag_filter = Filter::Linear;
    Filter min_filter = Filter::Linear;
    MipmapMode mipmap_mode = MipmapMode::Linear;
    // glTF min filters without a mip mode (NEAREST, LINEAR) sample level 0 only.
    float max_lod = 1000.0f; // VK_LOD_CLAMP_NONE
    AddressMode wrap_u = AddressMode::Repeat;
    AddressMode wrap_v = AddressMode::Repeat;
    bool operator==(const SamplerDesc&) const = default;
};
// Converts glTF filter/wrap enums (0 = unspecified). Unknown values throw
// std::invalid_argument naming the value.
SamplerDesc sampler_from_gltf(int mag_filter, int min_filter, int wrap_s, int wrap_t);

struct TextureRecord {
    std::string name;
    std::int32_t image = -1;   // index into Scene::images
    std::int32_t sampler = -1; // index into Scene::samplers, -1 = glTF default sampler
    std::uint8_t roles = kRoleNone;
};

struct ImageRecord {
    std::string name;
    std::string uri; // external or data URI (data URIs abbreviated), "" if bufferView
    std::int32_t buffer_view = -1;
    std::string mime_type;             // "image/png", "image/jpeg", ... or "image/x-sherpa-rgba8"
    std::uint64_t byte_size = 0;       // encoded bytes
    std::vector<std::uint8_t> encoded; // encoded source bytes (hashed by the texture cache)
    // Set only for images generated in code (built-in scenes): raw RGBA8 pixels.
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> pixels;
};

} // namespace sherpa::scene
