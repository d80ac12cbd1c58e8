#include "view_catalog.h"

#include <sherpa/render/debug_views.h>

namespace sherpa::editor {

namespace {
QString translated(const char* label) {
    return QCoreApplication::translate(render::kViewLabelContext, label);
}
} // namespace

std::vector<ViewEntry> ViewCatalog::views() {
    std::vector<ViewEntry> out;
    // The viewport rasterizes: views only rays draw (ao, shadow-error) are left out.
    for (const render::DebugViewInfo& v : render::kDebugViews)
        if (render::raster_view(v.id))
            out.push_back({v.name.data(), translated(v.label), static_cast<std::uint32_t>(v.id)});
    return out;
}

std::vector<ViewEntry> ViewCatalog::overlays() {
    std::vector<ViewEntry> out;
    for (const render::OverlayEntry& o : render::kOverlays)
        if (o.label) out.push_back({o.name.data(), translated(o.label), o.bit});
    return out;
}

std::optional<std::uint32_t> ViewCatalog::viewId(const QString& name) {
    if (auto v = render::find_debug_view(name.toStdString()); v && render::raster_view(*v))
        return static_cast<std::uint32_t>(*v);
    return std::nullopt;
}

QString ViewCatalog::viewName(std::uint32_t id) {
    if (id >= render::kDebugViews.size()) return {};
    return QString::fromLatin1(render::kDebugViews[id].name.data());
}

std::uint32_t ViewCatalog::cullBoxesOverlay() {
    return render::kOverlayCullBoxes;
}

} // namespace sherpa::editor
