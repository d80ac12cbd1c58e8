// CompareController: side B's file, the mode switch's effects on the viewport, the
// legend and the ray tracer's refusals.
#include "compare_controller.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QStatusBar>

#include "compare_controls.h"
#include "difference_legend.h"
#include "editor_context.h"
#include "load_controller.h"
#include "log_dock.h"
#include "render_controller.h"
#include "viewport_window.h"

namespace sherpa::editor {

CompareController::CompareController(EditorContext& context, CompareState& state,
                                     CompareControls& controls, DifferenceLegend& legend,
                                     LogDock& log, ViewportWindow& viewport, LoadController& loads,
                                     RenderController& frames, QMainWindow& window)
    : QObject(&window), context_(context), state_(state), controls_(controls), legend_(legend),
      log_(log), viewport_(viewport), loads_(loads), window_(window) {
    loader_.setParent(this); // a member: it leaves the children before QObject deletes them
    loader_.setObjectName(QStringLiteral("compareLoader"));
    connectControls();
    connect(&frames, &RenderController::frameReported, this, &CompareController::onFrameReported);
    connect(&frames, &RenderController::deviceKnown, this,
            [this](const std::optional<tex::TextureTarget>& target, bool rays) {
                if (target) state_.setRayTracing(rays);
            });
    // Side B "this file, tangents by ..." follows the file (another file stays).
    connect(&loads, &LoadController::sceneLoaded, this, [this] {
        if (session_ && tangents_) compareWithTangents(*tangents_);
    });
}

void CompareController::connectControls() {
    connect(&state_, &CompareState::changed, this, &CompareController::onChanged);
    connect(&controls_, &CompareControls::otherFileRequested, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            &window_, tr("Compare with glTF scene"), QFileInfo(context_.sceneSpec()).path(),
            tr("glTF scenes (*.gltf *.glb);;All files (*)"));
        if (!path.isEmpty()) compareWithFile(path);
    });
    connect(&controls_, &CompareControls::sourceTexturesRequested, this, [this] {
        if (context_.scene()) compareWithFile(context_.sceneSpec(), true);
    });
    connect(&controls_, &CompareControls::tangentsRequested, this,
            [this](scene::TangentMethod method) {
                if (context_.scene()) compareWithTangents(method);
            });
    connect(&viewport_.divider(), &SplitDivider::moved, &state_, &CompareState::setDivider);
    connect(&loader_, &SceneLoadJob::loaded, this, &CompareController::onOtherLoaded);
    connect(&loader_, &SceneLoadJob::failed, this,
            [this](const QString& spec, const QString& error) {
                log_.append(LogDock::Level::Error,
                            tr("Side B: %1 could not be loaded: %2").arg(spec, error));
            });
}

void CompareController::onOtherLoaded(SharedSession session) {
    log_.append(LogDock::Level::Info, tr("Side B: %1 loaded.").arg(session->spec));
    session_ = std::move(session);
    state_.setOtherFile(label_, tangents_);
    // Comparing first: outside a comparison a change frees side B (onChanged).
    // The frame is drawn later (requestUpdate), with both set.
    if (!state_.comparison().comparing()) state_.setMode(ViewportMode::Split);
    state_.setSide(SideB::OtherFile);
}

void CompareController::compareWithFile(const QString& spec, bool source_textures) {
    log_.append(LogDock::Level::Info, tr("Side B: loading %1…").arg(spec));
    tex::PipelineOptions options = loads_.textureOptions();
    label_ = QFileInfo(spec).fileName();
    tangents_.reset();
    if (source_textures) {
        options.device_supports_bc = false; // RGBA8 as decoded from the images
        label_ = tr("%1, source textures").arg(label_);
    }
    loader_.start(spec, loads_.textureTarget(), options);
}

void CompareController::compareWithTangents(scene::TangentMethod method) {
    const QString spec = context_.sceneSpec();
    log_.append(LogDock::Level::Info, tr("Side B: loading %1 with tangents by %2…")
                                          .arg(spec, CompareControls::tangentMethodLabel(method)));
    label_ = tr("%1, tangents: %2")
                 .arg(QFileInfo(spec).fileName(), CompareControls::tangentMethodName(method));
    tangents_ = method;
    loader_.start(spec, loads_.textureTarget(), loads_.textureOptions(), method);
    // What side A's tangents are, so that the difference is read for what it is.
    const scene::Scene* scene = context_.scene();
    if (!scene) return;
    int authored = 0, generated = 0, none = 0;
    for (const scene::Mesh& m : scene->meshes) {
        if (m.topology() != scene::Topology::Triangles) continue;
        const scene::Provenance p = m.provenance_of(scene::VertexAttribute::Tangent);
        ++(p == scene::Provenance::Authored    ? authored
           : p == scene::Provenance::Generated ? generated
                                               : none);
    }
    log_.append(LogDock::Level::Info,
                tr("Side A's tangents: %1 primitive(s) authored, %2 exact MikkTSpace, %3 "
                   "none (no TANGENT, no normal texture: there B differs from no tangents).")
                    .arg(authored)
                    .arg(generated)
                    .arg(none));
}

void CompareController::fill(ViewportRequest& frame) const {
    frame.compare = state_.comparison();
    frame.compareSession = session_;
}

void CompareController::onChanged() {
    const ViewportComparison& c = state_.comparison();
    // The other file is loaded only while comparing: leaving frees it (the render
    // thread drops side B's renderer with the next frame that does not compare).
    if (!c.comparing() && session_) {
        session_.reset();
        state_.setOtherFile(QString());
        if (c.side == SideB::OtherFile) state_.setSide(SideB::RayTraced);
    }
    legend_.setScale(c.heat_max, c.threshold);
    legend_.setNumbers({});
    legend_.setVisible(c.mode == ViewportMode::Difference);
    viewport_.divider().setFraction(c.mode == ViewportMode::Split ? std::optional<float>(c.divider)
                                                                  : std::nullopt);
    if (c.rays() || c.comparing())
        window_.statusBar()->showMessage(
            tr("Overlays and the selection highlight are drawn in the Raster mode only."), 5000);
    viewport_.scheduleFrame();
}

void CompareController::onFrameReported(const FrameReport& report) {
    if (!report.refused.isEmpty()) {
        const QString text =
            tr("The ray tracer cannot draw this frame: %1. Back to Raster.").arg(report.refused);
        log_.append(LogDock::Level::Warning, text);
        window_.statusBar()->showMessage(text, 15000);
        state_.setMode(ViewportMode::Raster);
        return;
    }
    if (report.difference.valid) legend_.setNumbers(report.difference);
}

} // namespace sherpa::editor
