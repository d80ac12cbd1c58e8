#include <sherpa/render/frame_request.h>

namespace sherpa::render {

std::string_view to_string(DebugView v) {
    const auto i = static_cast<std::size_t>(v);
    return i < kDebugViews.size() ? kDebugViews[i].name : "?";
}

std::optional<DebugView> parse_debug_view(std::string_view name) {
    return find_debug_view(name);
}

std::vector<std::string_view> debug_view_names() {
    std::vector<std::string_view> out;
    for (const DebugViewInfo& v : kDebugViews) out.push_back(v.name);
    return out;
}

std::optional<Overlay> parse_overlay(std::string_view name) {
    return find_overlay(name);
}

std::string_view to_string(RendererKind k) {
    return k == RendererKind::RayTraced ? "rt" : "raster";
}

std::optional<RendererKind> parse_renderer(std::string_view name) {
    for (RendererKind k : {RendererKind::Raster, RendererKind::RayTraced})
        if (to_string(k) == name) return k;
    return std::nullopt;
}

bool ray_traced_view(DebugView v) {
    switch (v) {
    case DebugView::Normal:
    case DebugView::Tangent:
    case DebugView::Bitangent:
    case DebugView::TangentW:
    case DebugView::Uv0:
    case DebugView::Uv1:
    case DebugView::BaseColor:
    case DebugView::Metallic:
    case DebugView::Roughness:
    case DebugView::Occlusion:
    case DebugView::Emissive:
    case DebugView::Provenance:
    case DebugView::ShadingNormal:
    case DebugView::Specular:
    case DebugView::Shadow:
    case DebugView::AmbientOcclusion:
    case DebugView::ShadowError:
    case DebugView::Lit: // path traced (shaders/pt.rgen)
        return true;
    default:
        return false;
    }
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
    for (const OverlayEntry& o : kOverlays) out.push_back(o.name);
    return out;
}

void copy_lighting(const FrameRequest& from, FrameRequest& to) {
    to.environment_rotation = from.environment_rotation;
    to.environment_intensity = from.environment_intensity;
    to.background = from.background;
    to.clear_color = from.clear_color;
    to.sun = from.sun;
    to.energy_compensation = from.energy_compensation;
    to.anisotropy_lighting = from.anisotropy_lighting;
    to.tone_map = from.tone_map;
    to.exposure = from.exposure;
}

bool needs_all_streams(const FrameRequest& s) {
    const auto view = static_cast<std::size_t>(s.view);
    std::uint32_t streams = view < kDebugViews.size() ? kDebugViews[view].streams : ~0u;
    for (const OverlayEntry& o : kOverlays)
        if (s.overlays & o.bit) streams |= o.streams;
    return streams != 0;
}

StreamPolicy stream_policy(const FrameRequest& s) {
    return needs_all_streams(s) ? StreamPolicy::AllPresent : StreamPolicy::UsedByMaterials;
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

} // namespace sherpa::render
