#pragma once
// Dock 3: the selected material's GPUMaterialData as the GPU sees it. With a
// renderer attached the record is read back from the GPU material buffer; without
// one the importer's CPU record is shown and the dock says so.
#include <QDockWidget>

#include <functional>
#include <optional>
#include <vector>

#include <sherpa/scene/material.h>

class QLabel;
class QTableView;

namespace sherpa::editor {

class EditorContext;
class MaterialFieldsModel;

// What a renderer hands back for one material: the bytes in its buffer and how its
// bindless texture indices map to Scene::textures.
struct GpuMaterialReadback {
    scene::GPUMaterialData record{};
    std::vector<int> bindless_to_texture;
};
// Asks for material `material`'s record; `done` is called later on the GUI thread
// (nothing when there is no renderer or scene).
using MaterialReadbackDone = std::function<void(std::optional<GpuMaterialReadback>)>;
using MaterialReadback = std::function<void(int material, MaterialReadbackDone done)>;

class MaterialDock : public QDockWidget {
    Q_OBJECT
public:
    explicit MaterialDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();
    void setReadback(MaterialReadback readback);
    MaterialFieldsModel* model() const { return model_; }
    // The warning about extensions the material uses that are not drawn ("" if none).
    QString notDrawnText() const;

Q_SIGNALS:
    void selectTextureRequested(int texture);

private:
    void showMaterial();
    void showReadback(int material, std::optional<GpuMaterialReadback> gpu);

    const EditorContext& context_;
    MaterialFieldsModel* model_;
    QLabel* header_;
    QLabel* not_drawn_; // the extensions of the material that Sherpa does not draw
    QTableView* view_;
    MaterialReadback readback_;
};

} // namespace sherpa::editor
