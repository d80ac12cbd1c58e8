#include "format_values.h"

#include <QCoreApplication>
#include <QStringList>

namespace sherpa::editor::format {

namespace {
constexpr int kReadableDigits = 6;
constexpr int kFloatDigits = 9; // max_digits10 of float

QString join_vec(const float* v, int n, int digits) {
    QStringList parts;
    for (int i = 0; i < n; ++i) parts << QString::number(static_cast<double>(v[i]), 'g', digits);
    return QStringLiteral("(") + parts.join(QStringLiteral(", ")) + QStringLiteral(")");
}
} // namespace

QString number(double v) {
    return QString::number(v, 'g', kReadableDigits);
}

QString compact(double v) {
    return QString::number(v, 'g', 4);
}

QString exact(double v) {
    return QString::number(v, 'g', kFloatDigits);
}

QString vec(const float* v, int n) {
    return join_vec(v, n, kReadableDigits);
}

QString vecExact(const float* v, int n) {
    return join_vec(v, n, kFloatDigits);
}

QString bytes(std::uint64_t n) {
    if (n < 1024) return QCoreApplication::translate("Format", "%1 B").arg(n);
    if (n < 1024 * 1024)
        return QCoreApplication::translate("Format", "%1 KiB")
            .arg(static_cast<double>(n) / 1024.0, 0, 'f', 1);
    return QCoreApplication::translate("Format", "%1 MiB")
        .arg(static_cast<double>(n) / (1024.0 * 1024.0), 0, 'f', 2);
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

QString componentType(std::int32_t t) {
    const ComponentName* c = component_name(t);
    return c ? QString::fromLatin1(c->gltf)
             : QCoreApplication::translate("Format", "unknown (%1)").arg(t);
}

QString componentTypeShort(std::int32_t t) {
    const ComponentName* c = component_name(t);
    return c ? QString::fromLatin1(c->unit) : componentType(t);
}

QString provenance(scene::Provenance p) {
    switch (p) {
    case scene::Provenance::Authored:
        return QCoreApplication::translate("Format", "authored");
    case scene::Provenance::Generated:
        return QCoreApplication::translate("Format", "generated");
    case scene::Provenance::Defaulted:
        return QCoreApplication::translate("Format", "defaulted");
    }
    return {};
}

QString attribute(scene::VertexAttribute a) {
    const std::string_view n = scene::gltf_name(a); // glTF semantics are names, not prose
    return QString::fromUtf8(n.data(), static_cast<qsizetype>(n.size()));
}

QString alphaMode(scene::AlphaMode m) {
    switch (m) {
    case scene::AlphaMode::Opaque:
        return QStringLiteral("OPAQUE");
    case scene::AlphaMode::Mask:
        return QStringLiteral("MASK");
    case scene::AlphaMode::Blend:
        return QStringLiteral("BLEND");
    }
    return {};
}

QString roles(std::uint8_t r) {
    QStringList parts;
    if (r & scene::kRoleColor) parts << QCoreApplication::translate("Format", "colour (sRGB)");
    if (r & scene::kRoleLinear) parts << QCoreApplication::translate("Format", "linear data");
    if (r & scene::kRoleNormal) parts << QCoreApplication::translate("Format", "normal map");
    return parts.isEmpty() ? QCoreApplication::translate("Format", "unused")
                           : parts.join(QStringLiteral(", "));
}

QString primitiveMode(scene::PrimitiveMode m) {
    const std::string_view n = to_string(m);
    return QString::fromUtf8(n.data(), static_cast<qsizetype>(n.size()));
}

QString yesNo(bool b) {
    return b ? QCoreApplication::translate("Format", "yes")
             : QCoreApplication::translate("Format", "no");
}

} // namespace sherpa::editor::format
