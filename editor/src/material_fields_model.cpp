#include "material_fields_model.h"

#include <QFileInfo>
#include <cstddef>
#include <cstring>

#include "format_values.h"
#include "texture_table_model.h"

#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/material_extensions.h>

namespace sherpa::editor {

namespace {

enum class FieldType { Vec4, Float, TextureIndex, AlphaMode, Bool };

struct Field {
    std::size_t offset;
    const char* name;
    FieldType type;
    const char* gltf_property; // glTF JSON path, not translated (it is a file format name)
};

constexpr Field kFields[] = {
    {offsetof(scene::GPUMaterialData, base_color_factor), "base_color_factor", FieldType::Vec4,
     "pbrMetallicRoughness.baseColorFactor"},
    {offsetof(scene::GPUMaterialData, emissive_factor), "emissive_factor", FieldType::Vec4,
     "emissiveFactor, KHR_materials_emissive_strength"},
    {offsetof(scene::GPUMaterialData, metallic_factor), "metallic_factor", FieldType::Float,
     "pbrMetallicRoughness.metallicFactor"},
    {offsetof(scene::GPUMaterialData, roughness_factor), "roughness_factor", FieldType::Float,
     "pbrMetallicRoughness.roughnessFactor"},
    {offsetof(scene::GPUMaterialData, normal_scale), "normal_scale", FieldType::Float,
     "normalTexture.scale"},
    {offsetof(scene::GPUMaterialData, occlusion_strength), "occlusion_strength", FieldType::Float,
     "occlusionTexture.strength"},
    {offsetof(scene::GPUMaterialData, base_color_tex), "base_color_tex", FieldType::TextureIndex,
     "pbrMetallicRoughness.baseColorTexture"},
    {offsetof(scene::GPUMaterialData, emissive_tex), "emissive_tex", FieldType::TextureIndex,
     "emissiveTexture"},
    {offsetof(scene::GPUMaterialData, metallic_roughness_tex), "metallic_roughness_tex",
     FieldType::TextureIndex, "pbrMetallicRoughness.metallicRoughnessTexture"},
    {offsetof(scene::GPUMaterialData, normal_tex), "normal_tex", FieldType::TextureIndex,
     "normalTexture"},
    {offsetof(scene::GPUMaterialData, occlusion_tex), "occlusion_tex", FieldType::TextureIndex,
     "occlusionTexture"},
    {offsetof(scene::GPUMaterialData, alpha_cutoff), "alpha_cutoff", FieldType::Float,
     "alphaCutoff"},
    {offsetof(scene::GPUMaterialData, alpha_mode), "alpha_mode", FieldType::AlphaMode, "alphaMode"},
    {offsetof(scene::GPUMaterialData, double_sided), "double_sided", FieldType::Bool,
     "doubleSided"},
};
constexpr int kFieldCount = static_cast<int>(sizeof kFields / sizeof kFields[0]);

template <typename T> T read(const scene::GPUMaterialData& r, std::size_t offset) {
    T v;
    std::memcpy(&v, reinterpret_cast<const unsigned char*>(&r) + offset, sizeof v);
    return v;
}

} // namespace

MaterialFieldsModel::MaterialFieldsModel(QObject* parent) : QAbstractTableModel(parent) {}

void MaterialFieldsModel::setMaterial(SharedSession session, int material,
                                      const scene::GPUMaterialData& record, Source source,
                                      std::vector<int> bindless_to_texture) {
    beginResetModel();
    session_ = std::move(session);
    material_ = material;
    record_ = record;
    source_ = source;
    bindless_to_texture_ = std::move(bindless_to_texture);
    buildExtensionRows();
    endResetModel();
}

void MaterialFieldsModel::buildExtensionRows() {
    extension_rows_.clear();
    const scene::Scene* sc = scene();
    if (!sc || material_ < 0 || std::size_t(material_) >= sc->materials.size()) return;
    // The layout the renderer uploads (texture slots do not move blocks).
    const render::MaterialExtensionBuffer layout = render::build_material_extensions(
        sc->materials,
        [](const scene::TextureSlot&, sherpa::scene::TextureRole) { return gpu::kWhiteTexture; });
    const render::MaterialExtensionPlace& place = layout.places[std::size_t(material_)];
    if (!place.any()) return;
    const scene::MaterialInstance& m = sc->materials[std::size_t(material_)];
    const int word = int(render::kExtensionWordBytes);
    auto words = [](std::uint32_t w) {
        return w == render::kNoExtension ? tr("absent") : QString::number(w);
    };
    extension_rows_.push_back({int(place.index) * word, QStringLiteral("ext.index"),
                               QStringLiteral("extra.extensions = %1").arg(place.index),
                               QStringLiteral("uvec4"),
                               tr("ior %1, specular %2, clearcoat %3, sheen %4")
                                   .arg(words(place.ior), words(place.specular),
                                        words(place.clearcoat), words(place.sheen)),
                               -1});
    if (place.ior != render::kNoExtension)
        extension_rows_.push_back({int(place.ior) * word, QStringLiteral("ext.ior"),
                                   QStringLiteral("KHR_materials_ior.ior"), QStringLiteral("float"),
                                   format::number(*m.ior), -1});
    // One row per texture field: its bindless slot's source chain, or the default.
    auto texture_row = [this](int offset, const char* field, const char* property,
                              const scene::TextureSlot& slot) {
        extension_rows_.push_back({offset, QString::fromLatin1(field),
                                   QString::fromLatin1(property), QStringLiteral("uint"),
                                   slot.present() ? chain(slot.texture) : tr("default texture"),
                                   slot.present() ? slot.texture : -1});
    };
    if (place.specular != render::kNoExtension) {
        const scene::MaterialSpecular& sp = *m.specular;
        const int base = int(place.specular) * word;
        extension_rows_.push_back(
            {base + int(offsetof(render::GPUSpecularBlock, color_factor)),
             QStringLiteral("ext.specular.color_factor"),
             QStringLiteral("KHR_materials_specular.specularColorFactor, specularFactor"),
             QStringLiteral("vec4"),
             format::vec(glm::vec4(sp.specular_color_factor, sp.specular_factor)), -1});
        texture_row(base + int(offsetof(render::GPUSpecularBlock, specular_tex)),
                    "ext.specular.specular_tex", "KHR_materials_specular.specularTexture",
                    sp.specular);
        texture_row(base + int(offsetof(render::GPUSpecularBlock, specular_color_tex)),
                    "ext.specular.specular_color_tex",
                    "KHR_materials_specular.specularColorTexture", sp.specular_color);
    }
    if (place.clearcoat != render::kNoExtension) {
        const scene::MaterialClearcoat& cc = *m.clearcoat;
        const int base = int(place.clearcoat) * word;
        extension_rows_.push_back(
            {base + int(offsetof(render::GPUClearcoatBlock, factors)),
             QStringLiteral("ext.clearcoat.factors"),
             QStringLiteral("KHR_materials_clearcoat.clearcoatFactor, clearcoatRoughnessFactor, "
                            "clearcoatNormalTexture.scale"),
             QStringLiteral("vec4"),
             format::vec(glm::vec4(cc.factor, cc.roughness_factor, cc.normal_scale, 0.0f)), -1});
        texture_row(base + int(offsetof(render::GPUClearcoatBlock, clearcoat_tex)),
                    "ext.clearcoat.clearcoat_tex", "KHR_materials_clearcoat.clearcoatTexture",
                    cc.clearcoat);
        texture_row(base + int(offsetof(render::GPUClearcoatBlock, roughness_tex)),
                    "ext.clearcoat.roughness_tex",
                    "KHR_materials_clearcoat.clearcoatRoughnessTexture", cc.roughness);
        texture_row(base + int(offsetof(render::GPUClearcoatBlock, normal_tex)),
                    "ext.clearcoat.normal_tex", "KHR_materials_clearcoat.clearcoatNormalTexture",
                    cc.normal);
    }
    if (place.sheen != render::kNoExtension) {
        const scene::MaterialSheen& sh = *m.sheen;
        const int base = int(place.sheen) * word;
        extension_rows_.push_back(
            {base + int(offsetof(render::GPUSheenBlock, factors)),
             QStringLiteral("ext.sheen.factors"),
             QStringLiteral("KHR_materials_sheen.sheenColorFactor, sheenRoughnessFactor"),
             QStringLiteral("vec4"), format::vec(glm::vec4(sh.color_factor, sh.roughness_factor)),
             -1});
        texture_row(base + int(offsetof(render::GPUSheenBlock, color_tex)), "ext.sheen.color_tex",
                    "KHR_materials_sheen.sheenColorTexture", sh.color);
        texture_row(base + int(offsetof(render::GPUSheenBlock, roughness_tex)),
                    "ext.sheen.roughness_tex", "KHR_materials_sheen.sheenRoughnessTexture",
                    sh.roughness);
    }
    appendTransmissionRows(place, m);
    appendMicrofacetRows(place, m);
}

QVariant MaterialFieldsModel::extensionData(const ExtensionRow& r, int column, int role) const {
    if (role == TextureRole) return r.texture;
    if (role != Qt::DisplayRole) return {};
    switch (column) {
    case OffsetColumn:
        return r.offset;
    case FieldColumn:
        return r.field;
    case PropertyColumn:
        return r.property;
    case TypeColumn:
        return r.type;
    case ValueColumn:
        return r.value;
    default:
        return {};
    }
}

void MaterialFieldsModel::clear() {
    beginResetModel();
    session_.reset();
    material_ = -1;
    extension_rows_.clear();
    endResetModel();
}

const scene::SpecularGlossiness* MaterialFieldsModel::specGloss() const {
    if (!scene() || material_ < 0 || std::size_t(material_) >= scene()->materials.size())
        return nullptr;
    const auto& sg = scene()->materials[std::size_t(material_)].specular_glossiness;
    return sg ? &*sg : nullptr;
}

// Rows: workflow, specular_glossiness (xyz specularFactor, w glossinessFactor), the
// texture. The extension's diffuse is in base_color_factor / base_color_tex.
QVariant MaterialFieldsModel::specGlossData(int row, int column) const {
    const scene::SpecularGlossiness& sg = *specGloss();
    static constexpr std::size_t kOffsets[] = {
        offsetof(render::GPUMaterialExtra, workflow),
        offsetof(render::GPUMaterialExtra, specular_glossiness),
        offsetof(render::GPUMaterialExtra, specular_glossiness_tex)};
    static constexpr const char* kNames[] = {"extra.workflow", "extra.specular_glossiness",
                                             "extra.specular_glossiness_tex"};
    static constexpr const char* kProperties[] = {
        "KHR_materials_pbrSpecularGlossiness",
        "KHR_materials_pbrSpecularGlossiness.specularFactor, glossinessFactor",
        "KHR_materials_pbrSpecularGlossiness.specularGlossinessTexture"};
    switch (column) {
    case OffsetColumn:
        return static_cast<int>(kOffsets[row]);
    case FieldColumn:
        return QString::fromLatin1(kNames[row]);
    case PropertyColumn:
        return QString::fromLatin1(kProperties[row]);
    case TypeColumn:
        return row == 1 ? QStringLiteral("vec4") : QStringLiteral("uint");
    case ValueColumn:
        if (row == 0)
            return QStringLiteral("%1 (specular-glossiness)")
                .arg(render::kWorkflowSpecularGlossiness);
        if (row == 1) return format::vec(glm::vec4(sg.specular_factor, sg.glossiness_factor));
        return sg.specular_glossiness.present() ? QString::number(sg.specular_glossiness.texture)
                                                : tr("default texture");
    case ChainColumn:
        if (row != 2) return {};
        return sg.specular_glossiness.present() ? chain(sg.specular_glossiness.texture)
                                                : tr("default texture");
    default:
        return {};
    }
}

int MaterialFieldsModel::textureOfRow(int row) const {
    if (row == kFieldCount + 2 && specGloss() && specGloss()->specular_glossiness.present())
        return specGloss()->specular_glossiness.texture;
    if (!scene() || row < 0 || row >= kFieldCount) return -1;
    if (kFields[row].type != FieldType::TextureIndex) return -1;
    const auto value = read<std::uint32_t>(record_, kFields[row].offset);
    if (value == scene::kTextureSentinel) return -1;
    int texture = static_cast<int>(value);
    if (source_ == Source::GpuReadback)
        texture = value < bindless_to_texture_.size() ? bindless_to_texture_[value] : -1;
    return texture >= 0 && static_cast<std::size_t>(texture) < scene()->textures.size() ? texture
                                                                                        : -1;
}

QString MaterialFieldsModel::chain(int texture) const {
    const scene::TextureRecord& t = scene()->textures[static_cast<std::size_t>(texture)];
    QString text = tr("texture %1").arg(texture);
    if (!t.name.empty()) text += QStringLiteral(" \"%1\"").arg(QString::fromStdString(t.name));
    if (t.image >= 0) {
        const scene::ImageRecord& img = scene()->images[static_cast<std::size_t>(t.image)];
        const QString where = !img.uri.empty()
                                  ? QFileInfo(QString::fromStdString(img.uri)).fileName()
                              : img.buffer_view >= 0 ? tr("bufferView %1").arg(img.buffer_view)
                                                     : tr("generated");
        text += tr(" → image %1 (%2)").arg(t.image).arg(where);
    }
    // The texture cache's state of the texture as prepared for the viewport (none
    // without a device: nothing was prepared, so nothing is said).
    if (const tex::PreparedTexture* r = TextureTableModel::preparedRecord(*session_, texture))
        text += tr(" → cache: %1").arg(TextureTableModel::cacheStateText(*r));
    return text;
}

int MaterialFieldsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || material_ < 0
               ? 0
               : kFieldCount + specGlossRows() + int(extension_rows_.size());
}

int MaterialFieldsModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MaterialFieldsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || material_ < 0) return {};
    if (index.row() >= kFieldCount + specGlossRows())
        return extensionData(
            extension_rows_[std::size_t(index.row() - kFieldCount - specGlossRows())],
            index.column(), role);
    if (index.row() >= kFieldCount) {
        if (role == TextureRole) return textureOfRow(index.row());
        return role == Qt::DisplayRole && specGloss()
                   ? specGlossData(index.row() - kFieldCount, index.column())
                   : QVariant();
    }
    const Field& f = kFields[index.row()];
    const int texture = textureOfRow(index.row());
    if (role == TextureRole) return texture;
    if (role == Qt::DecorationRole && index.column() == ChainColumn && texture >= 0 && session_ &&
        static_cast<std::size_t>(texture) < session_->thumbnails.size())
        return session_->thumbnails[static_cast<std::size_t>(texture)].scaled(
            24, 24, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    if (role == Qt::ToolTipRole && index.column() == ChainColumn && texture >= 0)
        return tr("Double-click to show this texture in the texture dock");
    if ((role == Qt::ToolTipRole || role == format::kExactTextRole) &&
        index.column() == ValueColumn) { // the value the GPU holds, every digit
        if (f.type == FieldType::Vec4) return format::vecExact(read<glm::vec4>(record_, f.offset));
        if (f.type == FieldType::Float) return format::exact(read<float>(record_, f.offset));
    }
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
    case OffsetColumn:
        return static_cast<int>(f.offset);
    case FieldColumn:
        return QString::fromLatin1(f.name);
    case PropertyColumn:
        // Spec-gloss materials keep their diffuse where the base colour goes.
        if (specGloss() && f.offset == offsetof(scene::GPUMaterialData, base_color_factor))
            return QStringLiteral("KHR_materials_pbrSpecularGlossiness.diffuseFactor");
        if (specGloss() && f.offset == offsetof(scene::GPUMaterialData, base_color_tex))
            return QStringLiteral("KHR_materials_pbrSpecularGlossiness.diffuseTexture");
        return QString::fromLatin1(f.gltf_property);
    case TypeColumn:
        switch (f.type) {
        case FieldType::Vec4:
            return QStringLiteral("vec4");
        case FieldType::Float:
            return QStringLiteral("float");
        default:
            return QStringLiteral("uint");
        }
    case ValueColumn:
        switch (f.type) {
        case FieldType::Vec4:
            return format::vec(read<glm::vec4>(record_, f.offset));
        case FieldType::Float:
            return format::number(read<float>(record_, f.offset));
        case FieldType::TextureIndex: {
            const auto v = read<std::uint32_t>(record_, f.offset);
            return v == scene::kTextureSentinel ? tr("none (0x%1)").arg(v, 8, 16, QLatin1Char('0'))
                                                : QString::number(v);
        }
        case FieldType::AlphaMode: {
            const auto v = read<std::uint32_t>(record_, f.offset);
            return QStringLiteral("%1 (%2)").arg(v).arg(
                v <= 2 ? format::alphaMode(static_cast<scene::AlphaMode>(v)) : QStringLiteral("?"));
        }
        case FieldType::Bool:
            return read<std::uint32_t>(record_, f.offset);
        }
        return {};
    case ChainColumn:
        if (f.type != FieldType::TextureIndex) return {};
        return texture >= 0 ? chain(texture) : tr("default texture");
    default:
        return {};
    }
}

QVariant MaterialFieldsModel::headerData(int section, Qt::Orientation o, int role) const {
    // Rows are headed by their byte offset in the record, as a hex dump's lines are:
    // the Offset column would not fit a side dock beside the field and its value.
    if (o == Qt::Vertical && role == Qt::DisplayRole && section >= 0 && section < rowCount())
        return data(index(section, OffsetColumn), Qt::DisplayRole);
    if (o == Qt::Vertical && role == Qt::ToolTipRole) return tr("Byte offset in the record");
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case OffsetColumn:
        return tr("Offset");
    case FieldColumn:
        return tr("Field");
    case TypeColumn:
        return tr("Type");
    case ValueColumn:
        return tr("Value");
    case PropertyColumn:
        return tr("glTF property");
    case ChainColumn:
        return tr("Texture chain");
    default:
        return {};
    }
}

} // namespace sherpa::editor
