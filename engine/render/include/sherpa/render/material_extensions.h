#pragma once
// The material extension buffer (GPUExtensionIndex and the per-extension blocks of
// gpu_structs.h, read by shaders/include/material_ext.glsl): which materials get a
// block and where each block lies. Only materials that use a drawn extension appear; a
// scene where none does gets no words at all (and the renderer no buffer).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/render/gpu_material_ext_structs.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/material.h>
#include <sherpa/scene/texture_records.h>

namespace sherpa::render {

// KHR_texture_transform (and the TEXCOORD set) of a slot as the shaders read it.
GPUTextureTransform texture_transform(const scene::TextureSlot& slot);

// Where one material's blocks are, in 16-byte words from the buffer's start
// (kNoExtension where absent).
struct MaterialExtensionPlace {
    std::uint32_t index = kNoExtension; // GPUExtensionIndex: GPUMaterialExtra::extensions
    std::uint32_t ior = kNoExtension;
    std::uint32_t specular = kNoExtension;
    std::uint32_t clearcoat = kNoExtension;
    std::uint32_t sheen = kNoExtension;
    std::uint32_t transmission = kNoExtension, volume = kNoExtension;
    std::uint32_t diffuse_transmission = kNoExtension, dispersion = kNoExtension;
    std::uint32_t anisotropy = kNoExtension, iridescence = kNoExtension;
    bool any() const { return index != kNoExtension; }
};

struct MaterialExtensionBuffer {
    std::vector<glm::uvec4> words;              // the buffer's contents
    std::vector<MaterialExtensionPlace> places; // one per material
    // Materials whose transmission can be non-zero: what makes the renderer draw the
    // transmission background (TransmissionPass); 0 costs no target and no pass.
    std::uint32_t transmissive_materials = 0;
    // Materials with KHR_materials_anisotropy: what makes the environment's anisotropic
    // lookup table (environment_lut.h); 0 costs none.
    std::uint32_t anisotropic_materials = 0;
    std::uint64_t bytes() const { return words.size() * sizeof(glm::uvec4); }
};

// The bindless slot of a texture slot in a role (SceneTextures::field_slot), or the
// default where it is absent or failed: white, the flat normal for kRoleNormal.
using ExtensionTextureSlot =
    std::function<std::uint32_t(const scene::TextureSlot&, scene::TextureRole)>;

// Pure: the words for `materials`, in material order, each block right after its
// material's index.
MaterialExtensionBuffer
build_material_extensions(std::span<const scene::MaterialInstance> materials,
                          const ExtensionTextureSlot& texture_slot);

} // namespace sherpa::render
