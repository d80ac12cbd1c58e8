// MainWindow: the viewport's mode switch (raster, ray traced, split, difference),
// side B of a comparison (another file, or this one with source textures or with
// tangents by another method, loaded by its own SceneLoadJob, kept only while
// comparing with it), the split divider dragged in the viewport and the
// difference legend's numbers. One path: an action changes CompareControls' state,
// currentFrame() puts it into the next ViewportFrame, GpuViewport draws it.
#include "main_window.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QStatusBar>

#include "compare_controls.h"
#include "difference_legend.h"
#include "log_dock.h"
#include "viewport_window.h"

namespace sherpa::editor {

void MainWindow::connectCompare() {
    connect(compare_, &CompareControls::changed, this, &MainWindow::onCompareChanged);
    connect(compare_, &CompareControls::otherFileRequested, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Compare with glTF scene"), QFileInfo(context_.sceneSpec()).path(),
            tr("glTF scenes (*.gltf *.glb);;All files (*)"));
        if (!path.isEmpty()) compareWithFile(path);
    });
    connect(compare_, &CompareControls::sourceTexturesRequested, this, [this] {
        if (context_.scene()) compareWithFile(context_.sceneSpec(), true);
    });
    connect(compare_, &CompareControls::tangentsRequested, this, [this](TangentMethod method) {
        if (context_.scene()) compareWithTangents(method);
    });
    connect(viewport_, &ViewportWindow::dividerMoved, compare_, &CompareControls::setDivider);
    connect(&compare_loader_, &SceneLoadJob::loaded, this, [this](SharedSession session) {
        log_->append(LogDock::Level::Info, tr("Side B: %1 loaded.").arg(session->spec));
        compare_session_ = std::move(session);
        compare_->setOtherFile(compare_label_, compare_tangents_);
        // Comparing first: outside a comparison a change frees side B (onCompareChanged).
        // The frame is drawn later (requestUpdate), with both set.
        if (!compare_->state().comparing()) compare_->setMode(ViewportMode::Split);
        compare_->setSide(SideB::OtherFile);
    });
    connect(&compare_loader_, &SceneLoadJob::failed, this,
            [this](const QString& spec, const QString& error) {
                log_->append(LogDock::Level::Error,
                             tr("Side B: %1 could not be loaded: %2").arg(spec, error));
            });
}

void MainWindow::compareWithFile(const QString& spec, bool source_textures) {
    log_->append(LogDock::Level::Info, tr("Side B: loading %1…").arg(spec));
    tex::PipelineOptions options = textureOptions();
    compare_label_ = QFileInfo(spec).fileName();
    compare_tangents_.reset();
    if (source_textures) {
        options.device_supports_bc = false; // RGBA8 as decoded from the images
        compare_label_ = tr("%1, source textures").arg(compare_label_);
    }
    compare_loader_.start(spec, texture_target_, options);
}

void MainWindow::compareWithTangents(TangentMethod method) {
    const QString spec = context_.sceneSpec();
    log_->append(LogDock::Level::Info, tr("Side B: loading %1 with tangents by %2…")
                                           .arg(spec, CompareControls::tangentMethodLabel(method)));
    compare_label_ =
        tr("%1, tangents: %2")
            .arg(QFileInfo(spec).fileName(), CompareControls::tangentMethodName(method));
    compare_tangents_ = method;
    compare_loader_.start(spec, texture_target_, textureOptions(), method);
    // What side A's tangents are, so that the difference is read for what it is.
    const Scene* scene = context_.scene();
    if (!scene) return;
    int authored = 0, generated = 0, none = 0;
    for (const Mesh& m : scene->meshes) {
        if (m.topology() != Topology::Triangles) continue;
        const Provenance p = m.provenance_of(VertexAttribute::Tangent);
        ++(p == Provenance::Authored ? authored : p == Provenance::Generated ? generated : none);
    }
    log_->append(LogDock::Level::Info,
                 tr("Side A's tangents: %1 primitive(s) authored, %2 exact MikkTSpace, %3 "
                    "none (no TANGENT, no normal texture: there B differs from no tangents).")
                     .arg(authored)
                     .arg(generated)
                     .arg(none));
}

void MainWindow::onCompareChanged() {
    const ViewportComparison& c = compare_->state();
    // The other file is loaded only while comparing: leaving frees it (the render
    // thread drops side B's renderer with the next frame that does not compare).
    if (!c.comparing() && compare_session_) {
        compare_session_.reset();
        compare_->setOtherFile(QString());
        if (c.side == SideB::OtherFile) compare_->setSide(SideB::RayTraced);
    }
    legend_->setScale(c.heat_max, c.threshold);
    legend_->setNumbers({});
    legend_->setVisible(c.mode == ViewportMode::Difference);
    viewport_->setDivider(c.mode == ViewportMode::Split ? std::optional<float>(c.divider)
                                                        : std::nullopt);
    if (c.rays() || c.comparing())
        statusBar()->showMessage(
            tr("Overlays and the selection highlight are drawn in the Raster mode only."), 5000);
    viewport_->scheduleFrame();
}

void MainWindow::onRefused(const QString& why) {
    const QString text = tr("The ray tracer cannot draw this frame: %1. Back to Raster.").arg(why);
    log_->append(LogDock::Level::Warning, text);
    statusBar()->showMessage(text, 15000);
    compare_->setMode(ViewportMode::Raster);
}

} // namespace sherpa::editor
