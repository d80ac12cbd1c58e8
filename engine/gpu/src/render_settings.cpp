#include <sherpa/gpu/render_settings.h>

#include <array>
#include <utility>

namespace sherpa::gpu {

namespace {
constexpr std::array<std::pair<DebugView, std::string_view>, 17> kViews{{
    {DebugView::Lit, "lit"},
    {DebugView::Normal, "normal"},
    {DebugView::Tangent, "tangent"},
    {DebugView::Bitangent, "bitangent"},
    {DebugView::TangentW, "tangent-w"},
    {DebugView::Uv0, "uv0"},
    {DebugView::Uv1, "uv1"},
    {DebugView::Uv0Checker, "uv0-checker"},
    {DebugView::Uv1Checker, "uv1-checker"},
    {DebugView::BaseColor, "base-color"},
    {DebugView::Metallic, "metallic"},
    {DebugView::Roughness, "roughness"},
    {DebugView::Occlusion, "occlusion"},
    {DebugView::Emissive, "emissive"},
    {DebugView::GeometricVsShading, "geometric-vs-shading"},
    {DebugView::Provenance, "provenance"},
    {DebugView::ShadingNormal, "shading-normal"},
}};
constexpr std::array<std::pair<Overlay, std::string_view>, 6> kOverlays{{
    {kOverlayWireframe, "wireframe"},
    {kOverlayNormals, "normals"},
    {kOverlayTangents, "tangents"},
    {kOverlayBitangents, "bitangents"},
    {kOverlayBounds, "aabb"},
    {kOverlayCullBoxes, "cull-boxes"},
}};
} // namespace

std::string_view to_string(DebugView v) {
    for (auto& [view, name] : kViews)
        if (view == v) return name;
    return "?";
}

std::optional<DebugView> parse_debug_view(std::string_view name) {
    for (auto& [view, n] : kViews)
        if (n == name) return view;
    return std::nullopt;
}

std::vector<std::string_view> debug_view_names() {
    std::vector<std::string_view> out;
    for (auto& entry : kViews) out.push_back(entry.second);
    return out;
}

std::optional<Overlay> parse_overlay(std::string_view name) {
    for (auto& [overlay, n] : kOverlays)
        if (n == name) return overlay;
    return std::nullopt;
}

std::string_view to_string(CullPath p) {
    switch (p) {
    case CullPath::None:
        return "none";
    case CullPath::Cpu:
        return "cpu";
    case CullPath::Gpu:
        return "gpu";
    }
    return "?";
}

std::optional<CullPath> parse_cull_path(std::string_view name) {
    for (CullPath p : {CullPath::None, CullPath::Cpu, CullPath::Gpu})
        if (to_string(p) == name) return p;
    return std::nullopt;
}

std::vector<std::string_view> overlay_names() {
    std::vector<std::string_view> out;
    for (auto& entry : kOverlays) out.push_back(entry.second);
    return out;
}

bool needs_all_streams(const RenderSettings& s) {
    switch (s.view) {
    case DebugView::Lit:
    case DebugView::BaseColor:
    case DebugView::Metallic:
    case DebugView::Roughness:
    case DebugView::Occlusion:
    case DebugView::Emissive:
    case DebugView::Provenance:
        break;
    default:
        return true;
    }
    return (s.overlays & (kOverlayNormals | kOverlayTangents | kOverlayBitangents)) != 0;
}

bool prepass_enabled(PrepassMode mode, bool cpu_device) {
    // A CPU rasterizer (lavapipe) pays for the prepass with a second run of vertex
    // pulling, triangle setup and binning over every triangle, and its early depth
    // test already skips whole hidden blocks of a front-to-back-ish draw; measured
    // there the prepass costs more than the overdraw it saves (engine/gpu/README.md).
    // GPUs keep it: their cost is shading, and it shades each pixel once.
    switch (mode) {
    case PrepassMode::On:
        return true;
    case PrepassMode::Off:
        return false;
    case PrepassMode::Auto:
        break;
    }
    return !cpu_device;
}

} // namespace sherpa::gpu
