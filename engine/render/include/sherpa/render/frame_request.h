#pragma once
// What one frame asks of the renderer (Renderer::render, PresentedFrame,
// ComparisonFrame): size, camera, debug view, overlays, pose, highlight, lighting and
// passes. What a scene load fixes (streams, missing textures, hidden nodes) is the
// renderer's SceneSetup (scene_setup.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/render/camera.h>
#include <sherpa/render/debug_views.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/load_settings.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/shadow_cascades.h>

namespace sherpa::render {

// Which path culls the camera passes.
enum class CullPath : std::uint32_t {
    None, // draw every instance
    Cpu,  // CPU test, compacted instance ids written per frame
    Gpu,  // compute shader fills indirect commands; vkCmdDrawIndexedIndirectCount
};
std::string_view to_string(CullPath p);
std::optional<CullPath> parse_cull_path(std::string_view name);

// Which renderer draws the frame: the rasterizer (every view, overlays, lighting) or
// primary rays through the scene's acceleration structures (the surface-data views
// of ray_traced_view(); needs RendererOptions::ray_tracing on a device with it).
enum class RendererKind : std::uint32_t { Raster, RayTraced };
std::string_view to_string(RendererKind k);
std::optional<RendererKind> parse_renderer(std::string_view name); // "raster", "rt"
// Whether the ray tracer draws `v` (the same formula as the rasterizer, shared in
// shaders/include/surface_views.glsl); the others are refused, never drawn wrong.
bool ray_traced_view(DebugView v);

// Depth prepass before opaque shading. Auto picks per device (prepass_enabled).
enum class PrepassMode : std::uint32_t { Auto, On, Off };

// Views and overlays by their names in kDebugViews / kOverlays (debug_views.h):
// parsed once where a name enters (command line, editor settings), never per frame.
std::string_view to_string(DebugView v);
std::optional<DebugView> parse_debug_view(std::string_view name);
std::vector<std::string_view> debug_view_names();
std::optional<Overlay> parse_overlay(std::string_view name);
std::vector<std::string_view> overlay_names();

inline constexpr float kDefaultCheckerDensity = 8.0f;

// The path tracer (RendererKind::RayTraced, DebugView::Lit; docs/path_tracer.md): it
// accumulates samples across frames while nothing that changes the image changes
// (camera, size, scene, pose, visibility, lights, environment, these settings), and
// starts over when something does.
struct PathTraceSettings {
    std::uint32_t samples = 1;     // samples per pixel each frame adds (render --spp)
    std::uint32_t max_samples = 0; // the accumulation stops there (0: no limit)
    // Surface interactions a path scatters at: 0 shows emission only, 1 direct light.
    std::uint32_t max_bounces = 8;
    std::uint32_t seed = 0; // the same seed and sample count give the same image
    bool restart = false;   // start over this frame even if nothing changed
    // Next-event estimation of emissive triangles (off: BSDF sampling alone finds them,
    // the reference the light sampling is tested against).
    bool light_sampling = true;
    // Direct light from one shadow ray per surface, its light chosen in proportion to
    // what each would bring (off: one ray per light, the reference it is tested against).
    bool one_light_ray = true;
};

struct FrameRequest {
    std::uint32_t width = 1280, height = 720;
    DebugView view = DebugView::Lit;
    std::uint32_t overlays = 0; // Overlay bits
    float glyph_length = 0.0f;  // world units; 0: 2% of the scene's bounding diagonal
    // Checks per UV unit of the uv checker views (atlas UVs need more than whole-
    // texture UVs); the checker is filtered, so any density is free of moiré.
    float uv_checker_density = kDefaultCheckerDensity;
    CameraSpec camera;
    RendererKind renderer = RendererKind::Raster;
    // >= 0: every material texture is sampled at this mip level by both renderers
    // (rays have no derivatives; comparing them needs the same texels). < 0: the
    // rasterizer uses derivatives, rays level 0.
    float texture_lod = -1.0f;
    PathTraceSettings path;
    bool shadows = true;
    std::uint32_t cascades = scene::kDefaultShadowCascades;
    // Hardware 2x2 PCF taps per shadow-map lookup (lit and shadow views): 1, 4 or 16;
    // 0 keeps the device's default (1 on CPU devices, 4 on GPUs: frame_data.cpp).
    std::uint32_t shadow_pcf_taps = 0;
    // Ray-traced sun visibility (shadow and shadow-error views): 1 ray is a hard
    // shadow; N > 1 rays spread over the sun's disc of this angular radius (radians),
    // at fixed stratified positions, so an image is reproducible.
    std::uint32_t shadow_rays = 1;
    float sun_angular_radius = 0.00465f; // the real sun's, 0.27 degrees
    // Ray-traced ambient occlusion (ao view): rays per pixel over the cosine-weighted
    // hemisphere and their length in world units (0: 5% of the scene's bounding diagonal).
    std::uint32_t ao_rays = 16;
    float ao_radius = 0.0f;
    // Reuse the shadow cascades while camera, light and scene are unchanged. False
    // re-renders them every frame (to measure their cost).
    bool cache_shadows = true;
    PrepassMode depth_prepass = PrepassMode::Auto;
    // Benchmark floor: the same draws with positions only and a constant colour.
    bool floor_only = false;
    glm::vec4 clear_color{0.18f, 0.19f, 0.21f, 1.0f}; // linear
    // Scene lights only; when the scene has no directional light a default sun
    // (and its shadows) is added.
    glm::vec3 sun_direction = scene::kDefaultSunDirection; // direction light travels
    float sun_intensity = 3.0f;
    // The default sun (and its shadow cascades) on or off; the scene's own lights are
    // drawn either way.
    bool sun = true;
    // The sky/ground ambient term, used only where no environment is loaded
    // (Renderer::set_environment); an environment replaces it.
    float ambient = 0.25f;
    // The loaded environment (environment.h): turned about +Y by this many degrees
    // (what was at direction d shows at R_y(rotation) d), its radiance scaled.
    float environment_rotation = 0.0f;
    float environment_intensity = 1.0f;
    // What shows where no surface is: the environment, it blurred, or clear_color. With no
    // environment loaded, always clear_color.
    Background background = Background::Environment;
    // Multiple-scattering energy compensation of the environment's specular light (rough
    // metals keep their energy); off shows single scattering alone.
    bool energy_compensation = true;
    // KHR_materials_anisotropy's environment specular (environment.h).
    AnisotropyLighting anisotropy_lighting = AnisotropyLighting::Lobe;
    // Display transform of the lit view: exposure in stops (0: radiance unchanged),
    // then the tone curve. Other views show data and are not tone-mapped.
    ToneMap tone_map = ToneMap::Neutral;
    float exposure = 0.0f;
    // Culls the camera pass and each shadow cascade (against its volume extended
    // toward the light, see sherpa/scene/shadow_cascades.h).
    CullPath cull = CullPath::Cpu;
    scene::CullMethod cull_method = scene::CullMethod::PVertex;
    // Check mode: the CPU test also runs on the GPU path, the GPU's visible sets are
    // read back and compared (CullStats::cpu_gpu_differences), and false positives
    // against the exact test are counted. Off, the GPU path does no per-object CPU
    // work except for blended instances (which the CPU sorts and draws one by one).
    bool cull_check = false;
    // Cull with this camera instead of the view camera (visual debugging of culling).
    std::optional<CameraSpec> freeze_cull;
    // Selection highlight (an editor's selection), drawn last: the instance (scene
    // instance index) outlined in kHighlightColor around its visible silhouette, its
    // surface left as shaded (a tint would hide the material the user selected it to
    // judge); one triangle of its mesh filled, and one vertex as a
    // normal/tangent/bitangent tripod, in kHighlightDetailColor, never hidden by depth.
    // Lines and points meshes, which have no silhouette, get their world box.
    // Ignored when the instance is not drawn (out of range, empty mesh, hidden).
    std::optional<std::uint32_t> highlight_instance;
    std::optional<std::uint32_t> highlight_triangle; // needs highlight_instance
    std::optional<std::uint32_t> highlight_vertex;   // needs highlight_instance
    // More instances outlined the same way (a selected node without a mesh: the
    // instances of its subtree). Not drawn ones are skipped.
    std::vector<std::uint32_t> highlight_outline;
    // The pose to draw (evaluate_pose(), morph weights possibly overridden by the editor); null:
    // the scene as loaded (bind pose, default weights). Skinned/morphed primitives are deformed
    // on the GPU; culling and shadows use the pose's conservative bounds.
    std::shared_ptr<const scene::Pose> pose;
    // A joint (node index) to highlight: the joint-influence view shows its weight as a heat
    // map, the skeleton overlay draws it in kHighlightDetailColor.
    std::optional<std::uint32_t> selected_joint;
};

inline const glm::vec4 kHighlightColor{1.0f, 0.45f, 0.0f, 1.0f};      // orange
inline const glm::vec4 kHighlightDetailColor{1.0f, 0.0f, 1.0f, 1.0f}; // magenta

// How the lit view is lit and shown, as the main view sets it: copies the environment
// rotation and intensity, background (and its clear colour), default sun, energy
// compensation, tone map and exposure of `from` into `to`, so that every frame of one
// scene (a comparison's two sides, the Lab's frames) is lit alike. The environment
// itself is the renderer's (Renderer::set_environment).
void copy_lighting(const FrameRequest& from, FrameRequest& to);

// The environment image and lighting settings of a view, for work that makes its own
// renderers (the Lab, `compare --image`): `environment` null is none.
struct Lighting {
    std::shared_ptr<const EnvironmentImage> environment;
    FrameRequest settings; // only copy_lighting()'s fields are read
};

// Does this view/overlay need streams the materials do not use (so the scene must
// be uploaded with StreamPolicy::AllPresent)?
bool needs_all_streams(const FrameRequest& settings);
// The stream policy a scene shown in `settings` is loaded with: AllPresent where
// needs_all_streams(), else UsedByMaterials.
StreamPolicy stream_policy(const FrameRequest& settings);

// Whether a frame of `triangles` at `pixels` draws the depth prepass: Auto draws it
// on GPUs, and on CPU devices unless the scene has more than one triangle per four
// pixels (see frame_request.cpp).
bool prepass_enabled(PrepassMode mode, bool cpu_device, std::uint64_t triangles,
                     std::uint64_t pixels);

} // namespace sherpa::render
