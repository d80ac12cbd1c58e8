#pragma once
// The engine renderer behind the viewport: a sherpa::gpu::Context adopting Qt's
// VkInstance, the Renderer, and a Presenter (the engine's swapchain) on the
// VkSurfaceKHR Qt made for the viewport window. Qt's QVulkanWindow is not used:
// Qt 6.4 cannot enable the Vulkan 1.3 features the engine needs.
#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <sherpa/render/environment.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/shadow_cascades.h>

#include "material_dock.h"
#include "scene_session.h"
#include "viewport_mode.h"

class QVulkanInstance;

namespace sherpa::gpu {
struct AccelerationStats;
class Renderer;
} // namespace sherpa::gpu

namespace sherpa::editor {

// How the lit view is lit and shown (the Environment menu, View > Tone mapping, the
// command line); the environment itself is the viewport's (GpuViewport::setEnvironment).
struct ViewportDisplay {
    float environmentRotation = 0.0f; // degrees about +Y
    float environmentIntensity = 1.0f;
    gpu::Background background = gpu::Background::Environment;
    glm::vec3 backgroundColor{0.18f, 0.19f, 0.21f}; // linear; Background::Color
    gpu::ToneMap toneMap = gpu::ToneMap::Neutral;
    float exposure = 0.0f; // stops
    bool sun = true;       // the default sun (scenes without lights)
    bool energyCompensation = true;
};

// The display's fields of `settings` (gpu::copy_lighting's): what every view of the
// window lit alike reads (the viewport, a comparison's side B, the Lab).
void apply_display(const ViewportDisplay& display, gpu::FrameRequest& settings);

// What the window wants drawn: the engine's FrameRequest as the window's controllers
// fill it (full size; GpuViewport::present() drops shadows from reduced frames, and
// overlays and highlight where rays draw), and what the viewport draws around it.
struct ViewportRequest {
    gpu::FrameRequest request;
    // Nodes unchecked in the scene tree (EditorContext::hiddenNodes()), given to the
    // renderer; null: all shown.
    std::shared_ptr<const std::vector<bool>> hiddenNodes;
    ViewportComparison compare;   // raster, ray traced, split or difference
    SharedSession compareSession; // SideB::OtherFile: the other file
};

// What one present() did, and what the renderer measured by then.
struct PresentOutcome {
    bool shown = false;       // false: skipped (swapchain recreated) or refused
    double gpu_ms = -1.0;     // timestamps of the latest completed frame
    bool cull_passes = false; // the renderer's culling passes are known
    // The last presented frame's culling passes from the renderer's history (camera,
    // then each cascade); `cached_shadows`: the cascades were reused, not drawn.
    std::vector<CullStats> passes;
    bool cached_shadows = false;
    // Not drawn: what the ray tracer refused (a view without a ray formula, a posed
    // frame...); empty when it drew.
    QString refused;
    DifferenceNumbers difference; // comparison frames: the latest completed difference
    // Path traced (ray-traced mode, lit view): samples per pixel accumulated as of the
    // latest completed frame (kFramesInFlight behind) and the estimated relative error,
    // measured at 4, 8, 16, ... samples (-1 before the first measurement).
    bool path_traced = false;
    std::uint32_t path_samples = 0;
    double path_error = -1.0;
};

class GpuViewport {
public:
    // Sets API version, extensions (and validation layer when on) that the engine
    // needs on a QVulkanInstance; call before create().
    static void configureInstance(QVulkanInstance& instance);
    // Null with `error` set when the device lacks what the engine needs. `ray_tracing`
    // (the command line's --rt on|off): enable it where the device has it; the
    // renderer then builds each scene's acceleration structures on upload.
    static std::unique_ptr<GpuViewport> create(QVulkanInstance& instance, bool ray_tracing,
                                               QString& error);
    ~GpuViewport();

    QString deviceName() const;
    // What the loader prepares textures for on this device (BC or not, BC7 decoded
    // for a CPU device, its name): plain data for tex::prepare_scene_textures() on
    // any thread.
    tex::TextureTarget textureTarget() const;
    // Whether frames drawn reduced (scale < 1, moving on a slow device) keep the
    // depth prepass the renderer would choose. Off by default: at a third of each
    // side DamagedHelmet's prepass saves about as much shading as it costs on
    // lavapipe (sherpa-bench-orbit: 1.00-1.22x the frame rate without it, four runs).
    void setReducedFramePrepass(bool prepass);
    // What an upload put on the GPU, for the docks.
    struct Uploaded {
        std::uint64_t textureBytes = 0; // the scene's textures
        // A copy of the scene's BLAS/TLAS statistics; null without ray tracing or a scene.
        std::shared_ptr<const gpu::AccelerationStats> acceleration;
    };
    // Uploads the session's scene with the textures the loader prepared for it (none:
    // uploaded without textures), the previous scene unloaded first; null unloads. The
    // streams are those the view and overlays of `frame` read (useStreamsFor()); slots
    // whose texture is missing or undecodable show a magenta/black checker in colour
    // slots (`missing_checker`) or the glTF defaults. The viewport keeps the session
    // alive while its scene is on the GPU.
    Uploaded load(SharedSession session, const ViewportRequest& frame, bool missing_checker);
    // The streams the view and overlays of `frame` read: a debug view of streams no
    // material reads uploads the scene again with every stream (when the view changes,
    // never per frame).
    void useStreamsFor(const ViewportRequest& frame);
    // The environment lighting lit frames: made on the GPU now (prefiltered), replacing
    // the one before; Kind::None removes it. Returns the warnings (an unreadable file
    // and the room used instead, NaN texels, ...).
    QStringList setEnvironment(const gpu::EnvironmentChoice& choice);
    // The scene last uploaded.
    const Scene* scene() const;
    // Whether the renderer ray traces (device support and --rt on).
    bool rayTracing() const;
    // Presents one frame on `surface` (the swapchain is created on first use and
    // recreated when the size changes), each side drawn at `scale` of the frame's
    // size and scaled up, without shadows (interaction on slow devices).
    PresentOutcome present(std::uint64_t surface, const ViewportRequest& frame, float scale = 1.0f);
    // Accumulation of the path-traced lit view (ray-traced mode) stops at this many
    // samples per pixel; every change starts it over.
    static constexpr std::uint32_t kPathSamples = 1024;
    // Waits until the queue is idle (the presented frame is on screen).
    void finish();
    // Drops the swapchain (before the window's surface goes away).
    void releaseSurface();
    // The material record as stored in the GPU buffer, and bindless slot -> texture.
    std::optional<GpuMaterialReadback> readMaterial(int material);
    // The latest completed frame pass by pass (GPU timestamps): "NAME MS ms" each, in
    // frame order.
    QStringList lastPassTimes() const;
    static constexpr std::size_t kFramesInFlight = 2; // gpu::Renderer::kFramesInFlight
    // Runs the renderer's GPU culling shader once for `frustum` over every instance
    // of the scene and compares its visible set with `cpu_visible` (per scene
    // instance). False without a scene.
    struct GpuCullCheck {
        double gpu_ms = -1.0;          // timestamped dispatch
        std::uint64_t visible = 0;     // objects the GPU keeps
        std::uint64_t differences = 0; // objects on which GPU and CPU disagree
    };
    bool checkGpuCulling(const Frustum& frustum, CullMethod method,
                         const std::vector<std::uint8_t>& cpu_visible, GpuCullCheck& out);
    // "NAME (Vulkan X.Y.Z)" of every physical device of `instance` (a VkInstance),
    // through the engine's enumeration.
    static QStringList deviceNames(void* instance);
    // The engine renderer behind the viewport, and through Renderer::context() its
    // device (validation log, resources): for callers on the render thread that use
    // the engine API directly.
    gpu::Renderer& renderer();

private:
    struct Impl;
    explicit GpuViewport(std::unique_ptr<Impl> impl);
    void upload();
    // present()'s frame; false when it was skipped or refused.
    bool draw(std::uint64_t surface, const ViewportRequest& frame, float scale);
    // What the renderer measured as of the frame just presented.
    PresentOutcome outcome(bool shown) const;
    void notePathSamples(const gpu::FrameRequest& settings);
    void preparePresenter(std::uint64_t surface, const gpu::FrameRequest& frame);
    // gpu_viewport_compare.cpp: side B loaded as `frame` asks, both drawn and composited.
    bool presentComparison(const ViewportRequest& frame, const gpu::FrameRequest& a, float scale);
    std::unique_ptr<Impl> impl_;
};

} // namespace sherpa::editor
