#pragma once
// Formatting of engine values for display: numbers at a readable precision (six
// significant digits; full float precision in tooltips and on copy), glTF enums
// by name, byte sizes. Every user-visible word is translated.
#include <QString>
#include <Qt>

#include <glm/glm.hpp>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

// Free functions; their words are translated in the context "Format", the one the
// catalogues (translations/) hold them in.
namespace format {

// Models answer this role with the exact text of a rounded number (copy, tooltips).
inline constexpr int kExactTextRole = Qt::UserRole + 0x45;

// Six significant digits: "0.0208333", not "0.0208333325".
QString number(double v);
// Nine significant digits: reads back as the same float (what the GPU sees).
QString exact(double v);
QString vec(const float* v, int n);
QString vecExact(const float* v, int n);
inline QString vecExact(glm::vec3 v) {
    return vecExact(&v.x, 3);
}
inline QString vecExact(glm::vec4 v) {
    return vecExact(&v.x, 4);
}
inline QString vec(glm::vec2 v) {
    return vec(&v.x, 2);
}
inline QString vec(glm::vec3 v) {
    return vec(&v.x, 3);
}
inline QString vec(glm::vec4 v) {
    return vec(&v.x, 4);
}
QString bytes(std::uint64_t n);
QString componentType(std::int32_t gltf_component_type);
// The same as a compact unit for narrow columns: i8, u8, i16, u16, u32, f32.
QString componentTypeShort(std::int32_t gltf_component_type);
// A number at four significant digits, for tables whose columns must fit a side
// dock (the vertex table's x, y, z); the exact value goes in the tooltip.
QString compact(double v);
QString provenance(scene::Provenance p);
QString attribute(scene::VertexAttribute a);
QString alphaMode(scene::AlphaMode m);
QString roles(std::uint8_t roles);
QString primitiveMode(scene::PrimitiveMode m);
QString yesNo(bool b);

} // namespace format

} // namespace sherpa::editor
