#pragma once
// The one list of material extension texture slots that are drawn: what the texture
// pipeline prepares (texture_uses), which TEXCOORD streams and tangents a mesh keeps
// (usage_report, mesh_tangents) and how a texture warning names its use
// (image_slot_uses) all read it. An extension's slots are listed only where the
// renderer draws the extension (render::build_material_extensions): not on unlit or
// specular-glossiness materials.
#include <sherpa/scene/material.h>
#include <sherpa/scene/texture_records.h>

#include <vector>

namespace sherpa::scene {

// Whether `m` draws its metallic-roughness extensions (KHR_materials_ior, _specular,
// _clearcoat...): false for unlit and specular-glossiness materials.
bool draws_material_extensions(const MaterialInstance& m);

struct ExtensionTextureSlot {
    const TextureSlot* slot;
    TextureRole role;
    const char* name; // "KHR_materials_clearcoat.clearcoatTexture"
};

// The drawn extension texture slots of `m` that name a texture.
std::vector<ExtensionTextureSlot> extension_texture_slots(const MaterialInstance& m);

// The normal maps `m` shades with (its own and a clearcoat's).
bool reads_normal_map(const MaterialInstance& m);
// Whether `m` draws KHR_materials_anisotropy (its direction lies in the tangent frame).
bool draws_anisotropy(const MaterialInstance& m);
// Where a normal map is read or anisotropy drawn, the mesh needs tangents.
bool needs_tangents(const MaterialInstance& m);
// The TEXCOORD set tangents are made for: the core normal map's, else the clearcoat
// normal map's, else the anisotropy texture's; 0 without any.
std::uint32_t tangent_uv_set(const MaterialInstance& m);

} // namespace sherpa::scene
