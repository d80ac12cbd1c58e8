#pragma once
// Shared look-ups of the material extension suites: a validation message by JSON
// pointer, and the extension buffer of a scene's materials with recognisable texture
// indices (100 + the glTF texture index; white where a slot is empty).
#include <sherpa/render/material_extensions.h>
#include <sherpa/scene/scene.h>

#include <cstdint>
#include <string>

namespace sherpa::test {

inline const scene::ValidationMessage* message_at(const scene::Scene& s,
                                                  const std::string& pointer) {
    for (const scene::ValidationMessage& m : s.validation.messages)
        if (m.pointer == pointer) return &m;
    return nullptr;
}

inline render::MaterialExtensionBuffer extension_layout(const scene::Scene& s) {
    return render::build_material_extensions(
        s.materials, [](const scene::TextureSlot& slot, scene::TextureRole) {
            return slot.present() ? 100u + std::uint32_t(slot.texture) : gpu::kWhiteTexture;
        });
}

} // namespace sherpa::test
