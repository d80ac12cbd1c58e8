#include <sherpa/render/render_settings.h>

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

bool prepass_enabled(PrepassMode mode, bool cpu_device, std::uint64_t triangles,
                     std::uint64_t pixels) {
    switch (mode) {
    case PrepassMode::On:
        return true;
    case PrepassMode::Off:
        return false;
    case PrepassMode::Auto:
        break;
    }
    // GPUs keep the prepass: their cost is shading, and it shades each pixel once.
    // A CPU rasterizer (lavapipe) pays for it with a second run of vertex pulling,
    // triangle setup and binning, per triangle; it saves the shading of hidden
    // pixels, per pixel. Measured there (engine/gpu/README.md) it pays off up to
    // DamagedHelmet's and 2CylinderEngine's densities (15k and 121k triangles at
    // 1280x720: ~10% faster) and costs ~25% at MetalRoughSpheresNoTextures' 1M.
    return !cpu_device || triangles * 4 <= pixels;
}

} // namespace sherpa::gpu
