#pragma once
// Formatting of engine values for display: numbers at a readable precision (six
// significant digits; full float precision in tooltips and on copy), glTF enums
// by name, byte sizes. Every user-visible word goes through tr().
#include <QCoreApplication>
#include <QString>
#include <Qt>

#include <glm/glm.hpp>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

class Format {
    Q_DECLARE_TR_FUNCTIONS(Format)
public:
    // Models answer this role with the exact text of a rounded number (copy, tooltips).
    static constexpr int kExactTextRole = Qt::UserRole + 0x45;

    // Six significant digits: "0.0208333", not "0.0208333325".
    static QString number(double v);
    // Nine significant digits: reads back as the same float (what the GPU sees).
    static QString exact(double v);
    static QString vec(const float* v, int n);
    static QString vecExact(const float* v, int n);
    static QString vecExact(glm::vec3 v) { return vecExact(&v.x, 3); }
    static QString vecExact(glm::vec4 v) { return vecExact(&v.x, 4); }
    static QString vec(glm::vec2 v) { return vec(&v.x, 2); }
    static QString vec(glm::vec3 v) { return vec(&v.x, 3); }
    static QString vec(glm::vec4 v) { return vec(&v.x, 4); }
    static QString bytes(std::uint64_t n);
    static QString componentType(std::int32_t gltf_component_type);
    // The same as a compact unit for narrow columns: i8, u8, i16, u16, u32, f32.
    static QString componentTypeShort(std::int32_t gltf_component_type);
    // A number at four significant digits, for tables whose columns must fit a side
    // dock (the vertex table's x, y, z); the exact value goes in the tooltip.
    static QString compact(double v);
    static QString provenance(Provenance p);
    static QString attribute(VertexAttribute a);
    static QString alphaMode(AlphaMode m);
    static QString roles(std::uint8_t roles);
    static QString primitiveMode(PrimitiveMode m);
    static QString yesNo(bool b);
};

} // namespace sherpa::editor
