#include "material_dock.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

#include <sherpa/scene/gltf_extensions.h>

#include "editor_context.h"
#include "material_fields_model.h"

namespace sherpa::editor {

MaterialDock::MaterialDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("materialDock"));
    model_ = new MaterialFieldsModel(this);
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    header_ = new QLabel(body);
    header_->setWordWrap(true);
    not_drawn_ = new QLabel(body);
    not_drawn_->setObjectName(QStringLiteral("notDrawnLabel"));
    not_drawn_->setWordWrap(true);
    not_drawn_->hide();
    view_ = new QTableView(body);
    view_->setModel(model_);
    // The vertical header shows each field's byte offset (MaterialFieldsModel).
    view_->verticalHeader()->setDefaultAlignment(Qt::AlignRight | Qt::AlignVCenter);
    view_->setWordWrap(false);
    view_->setIconSize(QSize(24, 24));
    view_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(header_);
    layout->addWidget(not_drawn_);
    layout->addWidget(view_);
    setWidget(body);
    connect(view_, &QTableView::doubleClicked, this, [this](const QModelIndex& index) {
        const int texture = index.data(MaterialFieldsModel::TextureRole).toInt();
        if (texture >= 0) Q_EMIT selectTextureRequested(texture);
    });
    connect(&context_.selection(), &SceneSelection::changed, this, &MaterialDock::showMaterial);
    retranslate();
}

void MaterialDock::setReadback(MaterialReadback readback) {
    readback_ = std::move(readback);
    showMaterial();
}

void MaterialDock::retranslate() {
    setWindowTitle(tr("Material SSBO"));
    showMaterial();
}

void MaterialDock::showMaterial() {
    const scene::Scene* scene = context_.scene();
    const int material = context_.selection().current().material;
    if (!scene || material < 0 || static_cast<std::size_t>(material) >= scene->materials.size()) {
        model_->clear();
        header_->setText(tr("No material selected."));
        not_drawn_->hide();
        return;
    }
    const scene::MaterialInstance& m = scene->materials[static_cast<std::size_t>(material)];
    // Loud about what is not drawn: a glass material shown opaque must say so.
    const std::vector<std::string> missing = scene::unsupported_extensions(m);
    QStringList names;
    for (const std::string& n : missing) names << QString::fromStdString(n);
    not_drawn_->setText(
        names.isEmpty()
            ? QString()
            : tr("⚠ Not drawn: %1. Sherpa does not implement %2, so this "
                 "material is shown without %2.")
                  .arg(names.join(QStringLiteral(", ")))
                  .arg(names.size() == 1 ? tr("this extension") : tr("these extensions")));
    not_drawn_->setVisible(!names.isEmpty());
    const QString name = m.name.empty() ? tr("(unnamed)") : QString::fromStdString(m.name);
    model_->setMaterial(context_.sharedSession(), material, scene::to_gpu_material(m),
                        MaterialFieldsModel::Source::Cpu);
    header_->setText(tr("Material %1 %2: the importer's CPU record (no renderer attached, so "
                        "texture fields hold glTF texture indices, not bindless slots).")
                         .arg(material)
                         .arg(name));
    // The GPU record replaces it when the render thread has read it back.
    if (readback_)
        readback_(material, [this, material,
                             scene = context_.scene()](std::optional<GpuMaterialReadback> gpu) {
            if (context_.scene() == scene && context_.selection().current().material == material)
                showReadback(material, std::move(gpu));
        });
}

QString MaterialDock::notDrawnText() const {
    return not_drawn_->text();
}

void MaterialDock::showReadback(int material, std::optional<GpuMaterialReadback> gpu) {
    if (!gpu) return;
    const scene::MaterialInstance& m =
        context_.scene()->materials[static_cast<std::size_t>(material)];
    const QString name = m.name.empty() ? tr("(unnamed)") : QString::fromStdString(m.name);
    model_->setMaterial(context_.sharedSession(), material, gpu->record,
                        MaterialFieldsModel::Source::GpuReadback,
                        std::move(gpu->bindless_to_texture));
    header_->setText(tr("Material %1 %2: 80-byte std430 record read back from the GPU "
                        "material buffer at offset %3.")
                         .arg(material)
                         .arg(name)
                         .arg(material * 80));
}

} // namespace sherpa::editor
