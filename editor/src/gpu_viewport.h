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
struct FrameRequest;
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

// What the window wants drawn; mapped to gpu::FrameRequest inside.
struct ViewportFrame {
    std::uint32_t width = 0, height = 0; // pixels
    CameraSpec camera;
    std::uint32_t view = 0;       // gpu::DebugView (ViewCatalog ids), Lit
    std::uint32_t overlays = 0;   // gpu::Overlay bits
    float checkerDensity = 32.0f; // uv checker views: checks per UV unit
    // Selection highlight: a scene instance, and a triangle / vertex of its mesh.
    std::optional<std::uint32_t> highlightInstance, highlightTriangle, highlightVertex;
    // More scene instances outlined: the selected node's own and, for a node without
    // a mesh, its subtree's (FrameRequest::highlight_outline).
    std::vector<std::uint32_t> outlineInstances;
    bool gpuCulling = false; // the renderer's GPU-driven culling path
    CullMethod cullMethod = CullMethod::PVertex;
    std::optional<CameraSpec> frozenCulling;    // cull from this camera instead
    std::shared_ptr<const Pose> pose;           // the timeline's; null: the scene as loaded
    std::optional<std::uint32_t> selectedJoint; // a joint node (skeleton, joint influence)
    // Nodes unchecked in the scene tree (EditorContext::hiddenNodes()); null: all shown.
    std::shared_ptr<const std::vector<bool>> hiddenNodes;
    ViewportComparison compare;   // raster, ray traced, split or difference
    SharedSession compareSession; // SideB::OtherFile: the other file
    // Shadow cascades and PCF taps (0: the device's default), as the Lab's shadows
    // family applies them; the map resolution is the viewport renderer's, fixed.
    std::uint32_t shadowCascades = kDefaultShadowCascades, shadowPcfTaps = 0;
    ViewportDisplay display;
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
    // Material slots whose texture is missing or undecodable: a magenta/black checker
    // in colour slots (true), or the glTF defaults (false). Applies at the next setSession().
    void setMissingTexturesChecker(bool checker);
    // Whether frames drawn reduced (scale < 1, moving on a slow device) keep the
    // depth prepass the renderer would choose. Off by default: at a third of each
    // side DamagedHelmet's prepass saves about as much shading as it costs on
    // lavapipe (sherpa-bench-orbit: 1.00-1.22x the frame rate without it, four runs).
    void setReducedFramePrepass(bool prepass);
    // Uploads the session's scene (replacing the previous one; null unloads) with the
    // textures the loader prepared for it (none: uploaded without textures). The
    // viewport keeps the session alive while its scene is on the GPU.
    void setSession(SharedSession session);
    // The streams the view and overlays of `frame` read: a debug view of streams no
    // material reads uploads the scene again with every stream (when the view changes,
    // never per frame).
    void useStreamsFor(const ViewportFrame& frame);
    // The environment lighting lit frames: made on the GPU now (prefiltered), replacing
    // the one before; Kind::None removes it. Returns the warnings (an unreadable file
    // and the room used instead, NaN texels, ...).
    QStringList setEnvironment(const gpu::EnvironmentChoice& choice);
    // The scene last uploaded.
    const Scene* scene() const;
    // Whether the renderer ray traces (device support and --rt on).
    bool rayTracing() const;
    // A copy of the uploaded scene's BLAS/TLAS statistics; null without ray tracing
    // or a scene.
    std::shared_ptr<const gpu::AccelerationStats> accelerationStats() const;
    // Presents one frame on `surface` (the swapchain is created on first use and
    // recreated when the size changes), each side drawn at `scale` of the frame's
    // size and scaled up, without shadows (interaction on slow devices). False when
    // it was skipped.
    bool present(std::uint64_t surface, const ViewportFrame& frame, float scale = 1.0f);
    // Why the last present() drew nothing: what the ray tracer refused (a view
    // without a ray formula, a posed frame...); empty when it drew.
    QString lastRefusal() const;
    // The path-traced lit view (ray-traced mode): samples per pixel accumulated as of
    // the latest completed frame (kFramesInFlight behind) and the estimated relative error,
    // measured at 4, 8, 16, ... samples (-1 before the first measurement). Accumulation stops at
    // kPathSamples; every change starts it over.
    static constexpr std::uint32_t kPathSamples = 1024;
    bool pathTraced() const; // the last present() drew the path tracer
    std::uint32_t pathSamples() const;
    double pathError() const;
    // The difference numbers of the latest completed comparison frame.
    DifferenceNumbers lastDifference() const;
    // Waits until the queue is idle (the presented frame is on screen).
    void finish();
    // Drops the swapchain (before the window's surface goes away).
    void releaseSurface();
    // The material record as stored in the GPU buffer, and bindless slot -> texture.
    std::optional<GpuMaterialReadback> readMaterial(int material);
    // Bytes of the loaded scene's textures on the GPU (0 without a scene).
    std::uint64_t textureBytes() const;
    // GPU time (timestamps, first to last pass) of the latest completed frame; -1
    // before one completed or without timestamps.
    double lastGpuMs() const;
    // The same frame pass by pass: "NAME MS ms" each, in frame order.
    QStringList lastPassTimes() const;
    static constexpr std::size_t kFramesInFlight = 2; // gpu::Renderer::kFramesInFlight
    // The last presented frame's culling passes from the renderer's history (camera,
    // then each cascade); false before any culled frame. `cached_shadows`: the cascades were
    // reused, not drawn.
    bool lastCullPasses(std::vector<CullStats>& passes, bool& cached_shadows) const;

private:
    void notePathSamples(const gpu::FrameRequest& settings);

public:
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
    void preparePresenter(std::uint64_t surface, const ViewportFrame& frame);
    // gpu_viewport_compare.cpp: side B loaded as `frame` asks, both drawn and composited.
    bool presentComparison(const ViewportFrame& frame, const gpu::FrameRequest& a, float scale);
    std::unique_ptr<Impl> impl_;
};

} // namespace sherpa::editor
