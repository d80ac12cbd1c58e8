#pragma once
// The viewport's A/B comparison: the mode switch (raster, ray traced, split,
// difference) in CompareControls, side B's other file (another file, or this one with
// source textures or with tangents by another method, loaded by its own SceneLoadJob
// and kept only while comparing with it), the split divider dragged in the viewport,
// the difference legend's numbers and what the ray tracer refuses. One path: an
// action changes the CompareState, fill() puts it into the next frame,
// ViewportPresenter draws it.
#include <QObject>
#include <QString>

#include <optional>

#include <sherpa/scene/tangents.h>

#include "gpu_viewport.h"
#include "scene_load_job.h"

class QMainWindow;

namespace sherpa::editor {

class CompareControls;
class CompareState;
class DifferenceLegend;
class EditorContext;
class LoadController;
class LogDock;
class RenderController;
class ViewportWindow;
struct FrameReport;

class CompareController : public QObject {
    Q_OBJECT
public:
    // `controls` (the menus over `state`) and `legend` are placed by the window
    // (toolbar, View menu, beside the viewport); side B's files load with `loads`'
    // texture settings.
    CompareController(EditorContext& context, CompareState& state, CompareControls& controls,
                      DifferenceLegend& legend, LogDock& log, ViewportWindow& viewport,
                      LoadController& loads, RenderController& frames, QMainWindow& window);

    CompareState& state() const { return state_; }
    // Loads `spec` as side B of the comparison (File dialog of "Another File…");
    // `source_textures`: its textures uploaded as decoded from their images, not
    // through BC7/BC5 (the compression's error against the source).
    void compareWithFile(const QString& spec, bool source_textures = false);
    // Loads this file again as side B with every triangle primitive's tangents made by
    // `method` (authored ones replaced), from the file's unsplit vertices.
    void compareWithTangents(scene::TangentMethod method);
    // The comparison and side B's other file in the next frame.
    void fill(ViewportRequest& frame) const;

private:
    void connectControls();
    void onChanged();
    void onOtherLoaded(SharedSession session);
    // A frame the ray tracer refused: said in the log and status bar, back to raster;
    // a comparison's numbers to the legend.
    void onFrameReported(const FrameReport& report);

    EditorContext& context_;
    CompareState& state_;
    CompareControls& controls_;
    DifferenceLegend& legend_;
    LogDock& log_;
    ViewportWindow& viewport_;
    LoadController& loads_;
    QMainWindow& window_;
    SceneLoadJob loader_;                          // side B's file
    SharedSession session_;                        // loaded by it, kept while comparing with it
    QString label_;                                // what side B shows (the file, its textures)
    std::optional<scene::TangentMethod> tangents_; // side B's tangents, when regenerated
};

} // namespace sherpa::editor
