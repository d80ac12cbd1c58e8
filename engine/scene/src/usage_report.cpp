#include <sherpa/scene/material_extension_slots.h>
#include <sherpa/scene/usage_report.h>

namespace sherpa::scene {

std::array<bool, kVertexAttributeCount> attributes_used(const MaterialInstance& material,
                                                        const Mesh& mesh) {
    std::array<bool, kVertexAttributeCount> used{};
    auto set = [&](VertexAttribute a) { used[static_cast<std::size_t>(a)] = true; };
    auto present = [&](VertexAttribute a) {
        return mesh.provenance_of(a) != Provenance::Defaulted;
    };
    set(VertexAttribute::Position);
    // Unlit materials shade without normals; everything else lights with them.
    if (!material.unlit) set(VertexAttribute::Normal);
    // Extension slots too (KHR_materials_pbrSpecularGlossiness, the drawn extensions'
    // slots): a texture read without its TEXCOORD stream would sample one texel everywhere.
    const TextureSlot none;
    std::vector<const TextureSlot*> slots{
        &material.base_color,
        &material.metallic_roughness,
        &material.normal,
        &material.occlusion,
        &material.emissive,
        material.specular_glossiness ? &material.specular_glossiness->specular_glossiness : &none};
    for (const ExtensionTextureSlot& e : extension_texture_slots(material)) slots.push_back(e.slot);
    for (const TextureSlot* slot : slots) {
        if (!slot->present()) continue;
        if (material.unlit && slot != &material.base_color)
            continue; // unlit reads base colour only
        if (slot->tex_coord == 0) set(VertexAttribute::TexCoord0);
        if (slot->tex_coord == 1) set(VertexAttribute::TexCoord1);
    }
    // Tangents matter only where a normal map perturbs the normal (glTF's rule) or an
    // anisotropy direction lies in the tangent frame.
    if (needs_tangents(material) && !material.unlit) set(VertexAttribute::Tangent);
    // Vertex colours multiply the base colour whenever the primitive has them.
    if (present(VertexAttribute::Color0)) set(VertexAttribute::Color0);
    // A stream the material wants but the mesh lacks is still not stored: shaders
    // read a default. Tangents are the exception: they are generated (MikkTSpace).
    for (VertexAttribute a : {VertexAttribute::TexCoord0, VertexAttribute::TexCoord1})
        if (!present(a)) used[static_cast<std::size_t>(a)] = false;
    return used;
}

std::array<bool, kVertexAttributeCount> mesh_attributes_used(const Scene& scene,
                                                             std::uint32_t mesh) {
    std::array<bool, kVertexAttributeCount> used{};
    for (std::uint32_t m : possible_materials(scene, mesh)) {
        if (m >= scene.materials.size()) continue;
        const auto one = attributes_used(scene.materials[m], scene.meshes[mesh]);
        for (std::size_t i = 0; i < used.size(); ++i) used[i] = used[i] || one[i];
    }
    return used;
}

UsageReport build_usage_report(const Scene& scene) {
    UsageReport report;
    std::vector<std::uint32_t> instance_count(scene.meshes.size(), 0);
    for (const auto& inst : scene.instances) ++instance_count[inst.mesh_id];
    for (std::uint32_t id = 0; id < scene.meshes.size(); ++id) {
        const Mesh& mesh = scene.meshes[id];
        PrimitiveUsage u;
        u.mesh_id = id;
        u.group_id = mesh.group_id;
        u.primitive_index = mesh.primitive_index;
        u.material_id = mesh.material_id;
        u.instances = instance_count[id];
        u.vertex_count = mesh.vertices.size();
        u.used = mesh_attributes_used(scene, id);
        for (VertexAttribute a : kAllVertexAttributes) {
            const auto i = static_cast<std::size_t>(a);
            u.present[i] = mesh.provenance_of(a) != Provenance::Defaulted;
            if (u.used[i]) u.used_bytes += std::uint64_t{stream_stride(a)} * u.vertex_count;
        }
        u.unified_bytes = std::uint64_t{sizeof(Vertex)} * u.vertex_count;
        if (u.present[static_cast<std::size_t>(VertexAttribute::Color0)])
            u.unified_bytes +=
                std::uint64_t{stream_stride(VertexAttribute::Color0)} * u.vertex_count;
        if (u.instances > 0) {
            report.used_bytes += u.used_bytes;
            report.unified_bytes += u.unified_bytes;
            for (std::size_t i = 0; i < kVertexAttributeCount; ++i)
                report.meshes_using[i] += u.used[i] ? 1 : 0;
        }
        report.primitives.push_back(u);
    }
    return report;
}

} // namespace sherpa::scene
