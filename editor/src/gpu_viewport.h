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

#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/scene.h>

#include "material_dock.h"

class QVulkanInstance;

namespace sherpa::gpu {
struct CullFrame;
}

namespace sherpa::editor {

// What the window wants drawn; mapped to gpu::RenderSettings inside.
struct ViewportFrame {
    std::uint32_t width = 0, height = 0; // pixels
    CameraSpec camera;
    QString view = QStringLiteral("lit");
    QStringList overlays;
};

class GpuViewport {
public:
    // Sets API version, extensions (and validation layer when on) that the engine
    // needs on a QVulkanInstance; call before create().
    static void configureInstance(QVulkanInstance& instance);
    // Null with `error` set when the device lacks what the engine needs.
    static std::unique_ptr<GpuViewport> create(QVulkanInstance& instance, QString& error);
    ~GpuViewport();

    QString deviceName() const;
    // Where setScene() finds and stores compressed textures, and the BC7 quality
    // ("fast", "balanced" or "best", as in the settings); an empty directory: no cache.
    void setTextureCache(const QString& directory, const QString& quality);
    // Uploads the scene (replacing the previous one; null unloads). Prepares its
    // textures (texture cache, BC7/BC5) on this thread first.
    void setScene(const Scene* scene);
    // Presents one frame on `surface` (the swapchain is created on first use and
    // recreated when the size changes). False when the frame was skipped.
    bool present(std::uint64_t surface, const ViewportFrame& frame);
    // Drops the swapchain (before the window's surface goes away).
    void releaseSurface();
    // The material record as stored in the GPU buffer, and bindless slot -> texture.
    std::optional<GpuMaterialReadback> readMaterial(int material);
    // Buffers, images and samplers alive in the engine (leak checks).
    std::int64_t objectCount() const;
    // Bytes of the loaded scene's textures on the GPU (0 without a scene).
    std::uint64_t textureBytes() const;
    double lastGpuMs() const { return last_gpu_ms_; }
    // The renderer's per-pass culling statistics of the last presented frames
    // (camera and each shadow cascade), oldest first.
    const RingHistory<gpu::CullFrame>& cullHistory() const;

private:
    struct Impl;
    explicit GpuViewport(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    double last_gpu_ms_ = 0.0;
};

} // namespace sherpa::editor
