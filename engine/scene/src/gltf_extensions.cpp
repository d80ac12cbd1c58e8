#include <sherpa/scene/gltf_extensions.h>

#include <algorithm>
#include <array>

namespace sherpa {
namespace {

constexpr std::array<std::string_view, 12> kSupported{
    "EXT_mesh_gpu_instancing",    // one engine instance per row (gltf_instancing.cpp)
    "EXT_meshopt_compression",    // through Debian's meshoptimizer
    "EXT_texture_webp",           // through OpenImageIO
    "KHR_draco_mesh_compression", // through Debian's Draco
    "KHR_meshopt_compression",    // where its bitstream version is one meshoptimizer decodes
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_unlit",
    "KHR_materials_pbrSpecularGlossiness", // shaded by its own definition (forward.frag)
    "KHR_mesh_quantization",               // every accessor component type is decoded
    "KHR_texture_basisu",                  // KTX2 (ETC1S / UASTC), engine/texture's transcoder
    "KHR_texture_transform",
};

} // namespace

std::span<const std::string_view> supported_gltf_extensions() {
    return kSupported;
}

bool is_supported_gltf_extension(std::string_view name) {
    return std::find(kSupported.begin(), kSupported.end(), name) != kSupported.end();
}

} // namespace sherpa
