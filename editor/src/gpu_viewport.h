#pragma once
// The engine behind the viewport, as Qt sees it: a sherpa::gpu::Context adopting Qt's
// VkInstance, the Renderer on it, and the three parts that drive the renderer: the
// scene on the GPU (ViewportScene), the presentation on the VkSurfaceKHR Qt made for
// the viewport window (ViewportPresenter, the engine's swapchain) and what the docks
// read back (ViewportReadbacks). Qt's QVulkanWindow is not used: Qt 6.4 cannot enable
// the Vulkan 1.3 features the engine needs. Made and used on the render thread only.
#include <QString>
#include <QStringList>

#include <memory>

#include <sherpa/texture/texture_target.h>

#include "viewport_presenter.h"
#include "viewport_readbacks.h"
#include "viewport_request.h"
#include "viewport_scene.h"

class QVulkanInstance;

namespace sherpa::render {
class Renderer;
} // namespace sherpa::render

namespace sherpa::gpu {
class Context;
} // namespace sherpa::gpu

namespace sherpa::editor {

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
    // "NAME (Vulkan X.Y.Z)" of every physical device of `instance` (a VkInstance),
    // through the engine's enumeration.
    static QStringList deviceNames(void* instance);
    ~GpuViewport();

    // "NAME (Vulkan X.Y.Z)" of the device in use.
    QString deviceName() const;
    // What the loader prepares textures for on this device (BC or not, BC7 decoded
    // for a CPU device, its name): plain data for tex::prepare_scene_textures() on
    // any thread.
    tex::TextureTarget textureTarget() const;
    // Whether the renderer ray traces (device support and --rt on).
    bool rayTracing() const;
    // A new scene for the viewport (null: none): what the docks read back of the old
    // one goes first (ViewportReadbacks::forgetScene), then ViewportScene::load().
    UploadedScene load(SharedSession session, const ViewportRequest& frame, bool missing_checker);
    ViewportScene& scene() { return *scene_; }
    ViewportPresenter& presenter() { return *presenter_; }
    ViewportReadbacks& readbacks() { return *readbacks_; }
    // The engine renderer behind the viewport, and through Renderer::context() its
    // device (validation log, resources): for callers on the render thread that use
    // the engine API directly (material variants, the test support's probes).
    render::Renderer& renderer() { return *renderer_; }
    // Waits until the queue is idle (the presented frame is on screen).
    void finish();

private:
    GpuViewport(std::unique_ptr<gpu::Context> context, bool ray_tracing);

    std::unique_ptr<gpu::Context> context_;
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<ViewportScene> scene_;
    std::unique_ptr<ViewportPresenter> presenter_;
    std::unique_ptr<ViewportReadbacks> readbacks_;
};

} // namespace sherpa::editor
