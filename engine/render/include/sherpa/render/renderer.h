#pragma once
// The renderer: what the CLI and the editor drive. It holds at most one scene on
// the GPU and records frames as an ordered list of passes (engine/render/src:
// culling, shadow cascades, depth prepass, forward shading, overlays, highlight),
// either into its own offscreen target (render()) or into a swapchain image through
// the RHI's Presenter (PresentedFrame, presented_frame.h, is the frame source). Set up
// once per scene (load() with a SceneSetup), then request frames (FrameRequest);
// statistics out. What a load fixes is the renderer's SceneState, how frames are
// recorded its FrameRecorder (both private to the render layer, engine/render/src). No
// Vulkan header here.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/render/acceleration_stats.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/render/load_settings.h>
#include <sherpa/render/path_trace.h>
#include <sherpa/render/scene_setup.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/shadow_cascades.h>

namespace sherpa::scene {
struct Scene;
} // namespace sherpa::scene

namespace sherpa {
namespace tex {
struct PreparedTextureSet;
}
} // namespace sherpa

namespace sherpa::gpu {
class Context;
class ResourceManager;
} // namespace sherpa::gpu

namespace sherpa::render {

class GpuScene;
class SceneState;
class FrameRecorder;

struct PassTiming {
    std::string name;
    double ms = 0.0;
};

// A path-traced frame: samples per pixel accumulated after it, those it added, and
// whether it started over.
struct PathTraceFrame {
    std::uint32_t samples = 0, added = 0;
    bool restarted = false;
};

// GPU-side measurements of one frame (timestamps and pipeline statistics of the
// camera passes; shadow cascades are timed but not in the statistics).
struct FrameStats {
    std::vector<PassTiming> passes;
    double gpu_ms = 0.0;
    bool shadows_rendered = false; // false when the cached cascades were reused
    std::uint64_t input_primitives = 0, vertex_invocations = 0, clipping_invocations = 0,
                  clipping_primitives = 0, fragment_invocations = 0;
    std::uint64_t draw_calls = 0;
    // Per culled view: "camera", then "cascade0".. for each shadow cascade. The camera
    // counts the shading draws (opaque, mask, blend) once; the depth prepass
    // repeats its opaque and mask draws and is counted in `prepass`. Cascade
    // statistics come from the last frame that rendered the cascades when they were
    // reused (`shadows_rendered` false). With culling off every instance is visible
    // and nothing is tested.
    std::vector<scene::CullStats> culling;
    scene::CullStats prepass; // depth prepass: draw_calls and triangles only
    PathTraceFrame path;      // a path-traced frame's accumulation
    const scene::CullStats* pass(std::string_view name) const {
        for (const scene::CullStats& c : culling)
            if (c.pass == name) return &c;
        return nullptr;
    }
};

// One frame's culling statistics, for the renderer's history.
struct CullFrame {
    CullPath path = CullPath::None;
    std::vector<scene::CullStats> passes;
    bool shadows_rendered = false;
};

// The path tracer's emissive light list (render/emissive_lights.h), made at load with
// ray tracing on.
struct EmissiveLightStats {
    std::size_t triangles = 0;         // sampled as lights (0: BSDF sampling only)
    std::uint32_t images_decoded = 0;  // emissive images decoded for it at load
    std::uint32_t images_reused = 0;   // those whose luminance the texture pipeline gave
    double build_ms = 0.0;             // CPU time of the list at load
    std::vector<std::string> warnings; // why emitters are not sampled: file, pointer, problem
};

// What a renderer holds between frames (Renderer::resident()).
struct ResidentStats {
    // The loaded scene's acceleration structures (BLAS/TLAS statistics); null without
    // RendererOptions::ray_tracing or a scene. Valid until the next load or unload.
    const AccelerationStats* acceleration = nullptr;
    // The environment: sizes, GPU bytes, build time (present false: none).
    EnvironmentStats environment;
    // Bytes of the renderer's own images (offscreen target, depth, shadow map, and the
    // transmission background below).
    std::uint64_t render_target_bytes = 0;
    // KHR_materials_transmission's background target and its depth (TransmissionPass):
    // 0 unless the scene has a transmissive material and the lit view was drawn.
    std::uint64_t transmission_target_bytes = 0;
    // The loaded scene's emissive light list (empty without ray tracing or a scene).
    EmissiveLightStats emissive;
};

// What set_material_variant() did: the variant now drawn and what changed for it.
struct VariantSwitch {
    std::int32_t variant = -1;    // -1: the file's default materials
    std::uint32_t meshes = 0;     // primitives (engine meshes) whose material changed
    std::uint32_t instances = 0;  // draws of them
    std::uint64_t gpu_bytes = 0;  // uploaded (the instance records' material words)
    bool culling_rebuilt = false; // an alpha mode or sidedness changed
    // With ray tracing: the geometry records whose material word followed (and their
    // bytes), the BLAS built opaque whose instances now force any-hit (a geometry whose
    // new material is masked, blended, or single-sided where the traversal does not cull),
    // the BLAS built to cull back faces whose instances no longer do (a material of it is
    // now double-sided), and whether the TLAS was rebuilt for those. No BLAS is rebuilt.
    std::uint32_t rt_records = 0;
    std::uint64_t rt_gpu_bytes = 0;
    std::uint32_t rt_forced_blas = 0;
    std::uint32_t rt_unculled_blas = 0;
    bool tlas_rebuilt = false;
};

struct RendererOptions {
    std::uint32_t shadow_resolution = scene::kDefaultShadowResolution;
    // How load(scene) without prepared textures prepares them; default: no disk
    // cache, BC where supported.
    TextureSettings textures;
    // Build each scene's acceleration structures on load (off the frame path) so that
    // FrameRequest::renderer = RayTraced can draw; needs a Context with
    // DeviceInfo::ray_tracing_enabled (else load() throws). Off: nothing RT is made (the
    // environment's sampling distribution included). The renderer's, not a load's.
    bool ray_tracing = false;
    // How they are built (scratch budget, compaction, posed BLAS refit or rebuild).
    AccelerationSettings acceleration;
};

class Renderer {
public:
    static constexpr std::uint32_t kFramesInFlight = 2;
    static constexpr std::size_t kCullHistory = 240;

    explicit Renderer(gpu::Context& context, const RendererOptions& options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Uploads `scene` as `setup` says, replacing the current one (freed once frames
    // using it finish). Prepares its textures first, on this thread, with
    // RendererOptions::textures.
    void load(const scene::Scene& scene, const SceneSetup& setup = {});
    // The same with textures already prepared for `scene` (prepare_scene_textures()
    // of the texture layer, for this device's texture_target(), e.g. on a loader
    // thread); only the upload happens here.
    void load(const scene::Scene& scene, std::shared_ptr<const tex::PreparedTextureSet> textures,
              const SceneSetup& setup = {});
    // The loaded scene's hidden nodes from now on (SceneSetup::hidden_nodes): applied
    // before the next frame; the same mask again costs one comparison.
    void set_hidden_nodes(std::shared_ptr<const std::vector<bool>> hidden);
    void unload();
    const GpuScene* scene() const;
    // What the renderer holds now: acceleration structures, environment, targets.
    ResidentStats resident() const;

    // The environment that lights lit frames (image-based lighting, environment.h): made
    // on the GPU from `image` (prefiltered cubes and lookup tables), replacing the one
    // before; null removes it (no GPU bytes, no passes: lit frames use the ambient term).
    // `options`: irradiance cube or SH9, specular cube size and samples (the defaults are
    // every view's). Waits for the frames in flight. Throws GpuError for an invalid image.
    void set_environment(const EnvironmentImage* image, const EnvironmentOptions& options = {});

    // Renders one frame offscreen and waits for it. With `rgba` set, reads the
    // image back as tightly packed sRGB-encoded RGBA8 rows, top row first.
    FrameStats render(const FrameRequest& settings, std::vector<std::uint8_t>* rgba = nullptr);

    // Culling statistics of the last frames whose results were read (render(),
    // presented frames), oldest first: what the editor's culling dock charts.
    const scene::RingHistory<CullFrame>& cull_history() const;

    gpu::ResourceManager& resources();
    gpu::Context& context();
    // The frame sources' narrow interface (PresentedFrame, ComparisonFrame,
    // render_comparison, read_path_trace, set_material_variant): frame slots, targets
    // and passes. Private to the render layer (src/frame_recorder.h); an incomplete
    // type elsewhere.
    FrameRecorder& frames();

private:
    gpu::Context& context_;
    std::unique_ptr<gpu::ResourceManager> resources_;
    std::unique_ptr<SceneState> scene_;     // what a load fixes
    std::unique_ptr<FrameRecorder> frames_; // what a frame records
};

// The path tracer's accumulation (its per-pixel sums, read back after the frames in
// flight; empty before the first path-traced frame), and its estimated error
// (path_trace.h). FrameStats::path counts the samples without a readback.
PathTraceImage read_path_trace(Renderer& renderer);

// Shows KHR_materials_variants variant `variant` (-1: the file's default materials)
// of the loaded scene without reloading it: only the materials its primitives draw
// with change (draw groups and the instance records' material word); every texture
// and vertex stream a variant reads was uploaded at load. Waits for the frames in
// flight. Throws std::out_of_range for a variant the scene does not have. The ray
// tracer keeps the materials the scene was loaded with and refuses frames while
// another variant is shown.
VariantSwitch set_material_variant(Renderer& renderer, std::int32_t variant);
PathTraceError path_trace_error(Renderer& renderer);

} // namespace sherpa::render
