#include "view_catalog.h"

namespace sherpa::editor {

std::vector<ViewEntry> ViewCatalog::views() {
    return {
        {"lit", tr("Lit")},
        {"normal", tr("Normals")},
        {"tangent", tr("Tangents")},
        {"bitangent", tr("Bitangents")},
        {"tangent-w", tr("Handedness (tangent w)")},
        {"uv0", tr("UV 0")},
        {"uv1", tr("UV 1")},
        {"uv0-checker", tr("UV 0 checker")},
        {"uv1-checker", tr("UV 1 checker")},
        {"base-color", tr("Base colour")},
        {"metallic", tr("Metallic")},
        {"roughness", tr("Roughness")},
        {"occlusion", tr("Occlusion")},
        {"emissive", tr("Emissive")},
        {"geometric-vs-shading", tr("Geometric vs shading normal")},
        {"provenance", tr("Tangent provenance")},
        {"shading-normal", tr("Shading normal")},
    };
}

std::vector<ViewEntry> ViewCatalog::overlays() {
    return {
        {"wireframe", tr("Wireframe")},     {"normals", tr("Normal glyphs")},
        {"tangents", tr("Tangent glyphs")}, {"bitangents", tr("Bitangent glyphs")},
        {"aabb", tr("Bounding boxes")},
    };
}

bool ViewCatalog::isView(const QString& name) {
    for (const ViewEntry& v : views())
        if (name == QLatin1String(v.name)) return true;
    return false;
}

} // namespace sherpa::editor
