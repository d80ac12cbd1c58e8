#pragma once
// What the docks read back of the scene on the viewport's GPU, on the render thread:
// a material's record as the GPU buffer holds it (material dock) and the GPU culling
// shader's visible set against the CPU's (culling dock). The culling check's buffers
// are built for one scene and go with it (forgetScene(), before the next upload).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <sherpa/scene/culling.h>
#include <sherpa/scene/culling_passes.h>

#include "culling_monitor.h"
#include "material_dock.h"

namespace sherpa::render {
class GpuCullChecker;
class Renderer;
} // namespace sherpa::render

namespace sherpa::gpu {
class Context;
} // namespace sherpa::gpu

namespace sherpa::editor {

class ViewportScene;

class ViewportReadbacks {
public:
    ViewportReadbacks(gpu::Context& context, render::Renderer& renderer,
                      const ViewportScene& scene);
    ~ViewportReadbacks();
    ViewportReadbacks(const ViewportReadbacks&) = delete;
    ViewportReadbacks& operator=(const ViewportReadbacks&) = delete;

    // The material record as stored in the GPU buffer, and bindless slot -> texture;
    // nullopt without a scene.
    std::optional<GpuMaterialReadback> readMaterial(int material);
    // Runs the renderer's GPU culling shader once for `frustum` over every instance
    // of the scene and compares its visible set with `cpu_visible` (per scene
    // instance); nullopt without a scene or instances.
    std::optional<GpuCullResult> checkGpuCulling(const scene::Frustum& frustum,
                                                 scene::CullMethod method,
                                                 const std::vector<std::uint8_t>& cpu_visible);
    // Frees what was built for the scene on the GPU (its culling check), before another
    // scene replaces it.
    void forgetScene();

private:
    gpu::Context& context_;
    render::Renderer& renderer_;
    const ViewportScene& scene_;
    std::unique_ptr<render::GpuCullChecker> culler_; // CPU/GPU agreement checks, built per scene
};

} // namespace sherpa::editor
