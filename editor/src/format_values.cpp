#include "format_values.h"

#include <QStringList>

namespace sherpa::editor {

namespace {
constexpr int kReadableDigits = 6;
constexpr int kFloatDigits = 9; // max_digits10 of float

QString join_vec(const float* v, int n, int digits) {
    QStringList parts;
    for (int i = 0; i < n; ++i) parts << QString::number(static_cast<double>(v[i]), 'g', digits);
    return QStringLiteral("(") + parts.join(QStringLiteral(", ")) + QStringLiteral(")");
}
} // namespace

QString Format::number(double v) {
    return QString::number(v, 'g', kReadableDigits);
}

QString Format::compact(double v) {
    return QString::number(v, 'g', 4);
}

QString Format::exact(double v) {
    return QString::number(v, 'g', kFloatDigits);
}

QString Format::vec(const float* v, int n) {
    return join_vec(v, n, kReadableDigits);
}

QString Format::vecExact(const float* v, int n) {
    return join_vec(v, n, kFloatDigits);
}

QString Format::bytes(std::uint64_t n) {
    if (n < 1024) return tr("%1 B").arg(n);
    if (n < 1024 * 1024) return tr("%1 KiB").arg(static_cast<double>(n) / 1024.0, 0, 'f', 1);
    return tr("%1 MiB").arg(static_cast<double>(n) / (1024.0 * 1024.0), 0, 'f', 2);
}

namespace {
// glTF componentType codes with their names, and as compact units for narrow columns.
struct ComponentName {
    std::int32_t code;
    const char* gltf;
    const char* unit;
};
constexpr ComponentName kComponentNames[] = {
    {5120, "BYTE", "i8"},          {5121, "UNSIGNED_BYTE", "u8"},
    {5122, "SHORT", "i16"},        {5123, "UNSIGNED_SHORT", "u16"},
    {5125, "UNSIGNED_INT", "u32"}, {5126, "FLOAT", "f32"}};

const ComponentName* component_name(std::int32_t t) {
    for (const ComponentName& c : kComponentNames)
        if (c.code == t) return &c;
    return nullptr;
}
} // namespace

QString Format::componentType(std::int32_t t) {
    const ComponentName* c = component_name(t);
    return c ? QString::fromLatin1(c->gltf) : tr("unknown (%1)").arg(t);
}

QString Format::componentTypeShort(std::int32_t t) {
    const ComponentName* c = component_name(t);
    return c ? QString::fromLatin1(c->unit) : componentType(t);
}

QString Format::provenance(Provenance p) {
    switch (p) {
    case Provenance::Authored:
        return tr("authored");
    case Provenance::Generated:
        return tr("generated");
    case Provenance::Defaulted:
        return tr("defaulted");
    }
    return {};
}

QString Format::attribute(VertexAttribute a) {
    const std::string_view n = gltf_name(a); // glTF semantics are names, not prose
    return QString::fromUtf8(n.data(), static_cast<qsizetype>(n.size()));
}

QString Format::alphaMode(AlphaMode m) {
    switch (m) {
    case AlphaMode::Opaque:
        return QStringLiteral("OPAQUE");
    case AlphaMode::Mask:
        return QStringLiteral("MASK");
    case AlphaMode::Blend:
        return QStringLiteral("BLEND");
    }
    return {};
}

QString Format::roles(std::uint8_t r) {
    QStringList parts;
    if (r & kRoleColor) parts << tr("colour (sRGB)");
    if (r & kRoleLinear) parts << tr("linear data");
    if (r & kRoleNormal) parts << tr("normal map");
    return parts.isEmpty() ? tr("unused") : parts.join(QStringLiteral(", "));
}

QString Format::primitiveMode(PrimitiveMode m) {
    const std::string_view n = to_string(m);
    return QString::fromUtf8(n.data(), static_cast<qsizetype>(n.size()));
}

QString Format::yesNo(bool b) {
    return b ? tr("yes") : tr("no");
}

} // namespace sherpa::editor
