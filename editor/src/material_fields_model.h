#pragma once
// The selected material's GPUMaterialData, field by field as the shader sees it
// (std430 offsets), with the glTF property each field came from and, for texture
// fields, the chain texture -> image -> source.
#include <QAbstractTableModel>
#include <QImage>

#include <memory>
#include <vector>

#include <sherpa/scene/material.h>
#include <sherpa/scene/scene.h>

#include "scene_session.h"

namespace sherpa::render {
struct MaterialExtensionPlace;
} // namespace sherpa::render

namespace sherpa::editor {

class MaterialFieldsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    // Field and value first: in a side dock of the default width (1600x1000) they
    // are what shows without scrolling (the value was cut off behind offset and type).
    enum Column {
        FieldColumn,
        ValueColumn,
        TypeColumn,
        OffsetColumn,
        PropertyColumn,
        ChainColumn,
        ColumnCount
    };
    static constexpr int TextureRole = Qt::UserRole + 1; // texture index of a row, -1 if none

    // Where the record came from: the renderer's GPU buffer (texture fields hold
    // bindless indices) or the importer's CPU record (glTF texture indices).
    enum class Source { Cpu, GpuReadback };

    explicit MaterialFieldsModel(QObject* parent = nullptr);
    // `bindless_to_texture` maps a GPU record's texture fields back to Scene::textures
    // (empty for a CPU record).
    void setMaterial(SharedSession session, int material, const scene::GPUMaterialData& record,
                     Source source, std::vector<int> bindless_to_texture = {});
    void clear();
    Source source() const { return source_; }
    const scene::GPUMaterialData& record() const { return record_; }
    // Scene::textures index a texture field refers to, -1 for the sentinel/defaults.
    int textureOfRow(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    QString chain(int texture) const;
    // KHR_materials_pbrSpecularGlossiness: the material's extension fields as rows
    // after the GPUMaterialData ones (GPUMaterialExtra, from the CPU record).
    const scene::SpecularGlossiness* specGloss() const;
    QVariant specGlossData(int row, int column) const;

    const scene::Scene* scene() const { return session_ ? session_->scene.get() : nullptr; }

    // Material extensions (KHR_materials_ior, _specular): one row per field of the
    // material's blocks in the extension buffer, its offset the byte offset there
    // (render::build_material_extensions' layout), values from the CPU record.
    struct ExtensionRow {
        int offset;
        QString field, property, type, value;
        int texture; // Scene::textures index, -1 if none
    };
    void buildExtensionRows();
    // The transmission family's rows (material_fields_transmission.cpp).
    void appendTransmissionRows(const render::MaterialExtensionPlace& place,
                                const scene::MaterialInstance& m);
    // KHR_materials_anisotropy's and _iridescence's rows (material_fields_microfacet.cpp).
    void appendMicrofacetRows(const render::MaterialExtensionPlace& place,
                              const scene::MaterialInstance& m);
    QVariant extensionData(const ExtensionRow& r, int column, int role) const;
    int specGlossRows() const { return specGloss() ? 3 : 0; }

    SharedSession session_; // the scene and its thumbnails
    int material_ = -1;
    scene::GPUMaterialData record_{};
    Source source_ = Source::Cpu;
    std::vector<int> bindless_to_texture_;
    std::vector<ExtensionRow> extension_rows_;
};

} // namespace sherpa::editor
