#include "variant_menu.h"

#include "editor_context.h"
#include "gpu_viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QEvent>
#include <QPointer>

#include <sherpa/render/renderer.h>

namespace sherpa::editor {

VariantMenu::VariantMenu(EditorContext& context, Poster post, QWidget* parent)
    : QMenu(parent), context_(context), post_(std::move(post)), group_(new QActionGroup(this)) {
    connect(&context_, &EditorContext::sceneReady, this, &VariantMenu::rebuild);
    rebuild();
}

void VariantMenu::rebuild() {
    for (QAction* a : group_->actions()) {
        group_->removeAction(a);
        delete a;
    }
    clear();
    variant_ = -1; // a loaded scene shows its default materials
    const scene::Scene* scene = context_.scene();
    const auto& names = scene ? scene->variants.names : std::vector<std::string>{};
    for (int v = -1; v < static_cast<int>(names.size()); ++v) {
        QAction* a = addAction(v < 0 ? QString() : QString::fromStdString(names[std::size_t(v)]));
        a->setCheckable(true);
        a->setChecked(v < 0);
        a->setData(v);
        group_->addAction(a);
        connect(a, &QAction::triggered, this, [this, v] { choose(v); });
        if (v < 0 && !names.empty()) addSeparator();
    }
    setEnabled(!names.empty());
    retranslate();
}

void VariantMenu::choose(int variant) {
    const scene::Scene* scene = context_.scene();
    if (!scene || variant < -1 || variant >= static_cast<int>(scene->variants.names.size()) ||
        variant == variant_)
        return;
    variant_ = variant;
    for (QAction* a : group_->actions()) a->setChecked(a->data().toInt() == variant);
    const QString name = variant < 0
                             ? tr("default materials")
                             : QString::fromStdString(scene->variants.names[std::size_t(variant)]);
    QPointer<VariantMenu> self(this);
    post_([self, variant, name](GpuViewport& gpu) {
        const render::VariantSwitch s = render::set_material_variant(gpu.renderer(), variant);
        QMetaObject::invokeMethod(qApp, [self, s, name] {
            if (self) Q_EMIT self->switched(describe(s, name));
        });
    });
}

QString VariantMenu::describe(const render::VariantSwitch& s, const QString& name) {
    // With ray tracing: the geometry records that followed, and any TLAS rebuild.
    QString rays;
    if (s.rt_records > 0)
        rays = tr("; ray tracer: %1 geometry record(s), %2 bytes")
                   .arg(s.rt_records)
                   .arg(qulonglong(s.rt_gpu_bytes));
    if (s.tlas_rebuilt)
        rays += tr(", TLAS rebuilt: any-hit forced on %1 BLAS built opaque, back-face culling "
                   "off on %2")
                    .arg(s.rt_forced_blas)
                    .arg(s.rt_unculled_blas);
    return tr("Material variant: %1 (%2 primitive(s), %3 draw(s) changed material; %4 GPU bytes "
              "uploaded%5; nothing reloaded).")
        .arg(name)
        .arg(s.meshes)
        .arg(s.instances)
        .arg(qulonglong(s.gpu_bytes))
        .arg((s.culling_rebuilt ? tr(", culling lists rebuilt for a changed alpha mode")
                                : QString()) +
             rays);
}

void VariantMenu::retranslate() {
    setTitle(tr("Va&riants"));
    for (QAction* a : group_->actions())
        if (a->data().toInt() < 0) a->setText(tr("&Default Materials"));
    setToolTip(isEnabled() ? QString() : tr("The file has no material variants"));
}

void VariantMenu::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QMenu::changeEvent(event);
}

} // namespace sherpa::editor
