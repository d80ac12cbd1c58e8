// The engine's headers come first (see gpu_viewport.cpp).
#include <sherpa/gpu/context.h>
#include <sherpa/render/cull_check.h>
#include <sherpa/render/material_readback.h>
#include <sherpa/render/renderer.h>

#include "viewport_readbacks.h"
#include "viewport_scene.h"

namespace sherpa::editor {

ViewportReadbacks::ViewportReadbacks(gpu::Context& context, render::Renderer& renderer,
                                     const ViewportScene& scene)
    : context_(context), renderer_(renderer), scene_(scene) {}

ViewportReadbacks::~ViewportReadbacks() = default;

std::optional<GpuMaterialReadback> ViewportReadbacks::readMaterial(int material) {
    const scene::Scene* scene = scene_.scene();
    if (!scene) return std::nullopt;
    std::optional<render::MaterialReadback> r = render::read_material(renderer_, *scene, material);
    if (!r) return std::nullopt;
    return GpuMaterialReadback{r->record, std::move(r->bindless_to_texture)};
}

std::optional<GpuCullResult>
ViewportReadbacks::checkGpuCulling(const scene::Frustum& frustum, scene::CullMethod method,
                                   const std::vector<std::uint8_t>& cpu_visible) {
    const scene::Scene* scene = scene_.scene();
    if (!scene || scene->instances.empty()) return std::nullopt;
    if (!culler_ || &culler_->scene() != scene)
        culler_ = std::make_unique<render::GpuCullChecker>(context_, renderer_.resources(), *scene);
    const render::GpuCullComparison r = culler_->compare(frustum, method, cpu_visible);
    return GpuCullResult{r.gpu_ms, static_cast<std::int64_t>(r.visible.size()), r.differences};
}

void ViewportReadbacks::forgetScene() {
    culler_.reset();
}

} // namespace sherpa::editor
