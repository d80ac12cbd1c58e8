#include "view_catalog.h"

#include <sherpa/render/debug_views.h>

namespace sherpa::editor {

namespace {
QString translated(const char* label) {
    return QCoreApplication::translate(gpu::kViewLabelContext, label);
}
} // namespace

std::vector<ViewEntry> ViewCatalog::views() {
    std::vector<ViewEntry> out;
    // The viewport rasterizes: views only rays draw (ao, shadow-error) are left out.
    for (const gpu::DebugViewInfo& v : gpu::kDebugViews)
        if (gpu::raster_view(v.id))
            out.push_back({v.name.data(), translated(v.label), static_cast<std::uint32_t>(v.id)});
    return out;
}

std::vector<ViewEntry> ViewCatalog::overlays() {
    std::vector<ViewEntry> out;
    for (const gpu::OverlayEntry& o : gpu::kOverlays)
        if (o.label) out.push_back({o.name.data(), translated(o.label), o.bit});
    return out;
}

std::optional<std::uint32_t> ViewCatalog::viewId(const QString& name) {
    if (auto v = gpu::find_debug_view(name.toStdString()); v && gpu::raster_view(*v))
        return static_cast<std::uint32_t>(*v);
    return std::nullopt;
}

QString ViewCatalog::viewName(std::uint32_t id) {
    if (id >= gpu::kDebugViews.size()) return {};
    return QString::fromLatin1(gpu::kDebugViews[id].name.data());
}

std::uint32_t ViewCatalog::cullBoxesOverlay() {
    return gpu::kOverlayCullBoxes;
}

} // namespace sherpa::editor
