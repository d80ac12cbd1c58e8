#pragma once
// The debug views and overlays the renderer offers, read from the engine's one table
// (sherpa/render/debug_views.h): names (settings, command line), ids the renderer
// takes, and labels translated here in the table's context.
#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace sherpa::editor {

struct ViewEntry {
    const char* name; // renderer's name, stable (settings, command line)
    QString label;    // translated
    std::uint32_t id; // render::DebugView value, or the render::Overlay bit
};

class ViewCatalog {
public:
    static std::vector<ViewEntry> views();
    static std::vector<ViewEntry> overlays(); // those of the Overlays menu
    static bool isView(const QString& name) { return viewId(name).has_value(); }
    static std::optional<std::uint32_t> viewId(const QString& name);
    static QString viewName(std::uint32_t id);
    static std::uint32_t cullBoxesOverlay(); // switched from the Culling menu
};

} // namespace sherpa::editor
