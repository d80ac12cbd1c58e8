// The ray-traced frame (RenderSettings::renderer = RayTraced): primary rays through
// the scene's acceleration structures, built on load, drawing the surface-data
// debug views with the rasterizer's formulas (rt_view_pass.h). Views and overlays
// the ray tracer has no formula for are refused, never drawn as something else.
#include "renderer_impl.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/scene/animation.h>
#include <sherpa/texture/mips.h>

#include <cmath>

namespace sherpa::gpu {
namespace {

std::uint8_t srgb_byte(float linear) {
    return static_cast<std::uint8_t>(
        std::lround(tex::linear_to_srgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0f));
}

std::string ray_traced_view_names() {
    std::string out;
    for (const DebugViewInfo& v : kDebugViews)
        if (ray_traced_view(v.id)) out += (out.empty() ? "" : ", ") + std::string(v.name);
    return out;
}

} // namespace

std::string unposed_motion_mesh(const Scene& scene) {
    if (scene.motions.empty()) return {};
    const Pose pose = evaluate_pose(scene, -1, 0.0);
    const float tolerance = 1e-4f * std::max(glm::length(scene.bounds.extent()), 1e-6f);
    for (std::uint32_t n : scene.displayed_nodes) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0) continue;
        for (const PrimitiveInfo& p : scene.primitives) {
            if (p.mesh != static_cast<std::uint32_t>(node.mesh) || p.engine_mesh < 0 ||
                p.motion < 0)
                continue;
            const std::vector<glm::vec3>& stored = scene.motions[p.motion].base_positions;
            const std::vector<glm::vec3> posed = posed_positions(scene, pose, n, p);
            const glm::mat4& world = pose.world[n];
            for (std::size_t i = 0; i < posed.size() && i < stored.size(); ++i)
                if (glm::distance(posed[i], glm::vec3(world * glm::vec4(stored[i], 1.0f))) >
                    tolerance)
                    return "mesh " + std::to_string(p.mesh) + " primitive " +
                           std::to_string(p.primitive) + " (node '" + node.name + "')";
        }
    }
    return {};
}

FrameStats Renderer::Impl::render_rt(const RenderSettings& settings,
                                     std::vector<std::uint8_t>* rgba) {
    if (!acceleration)
        throw GpuError("the ray tracer needs the scene's acceleration structures: create the "
                       "renderer with RendererOptions::ray_tracing on a device that ray traces");
    if (!ray_traced_view(settings.view))
        throw GpuError("the ray tracer does not draw view '" +
                       std::string(to_string(settings.view)) + "' (it draws " +
                       ray_traced_view_names() + ")");
    if (settings.overlays != 0 || settings.highlight_instance)
        throw GpuError("the ray tracer draws no overlays or highlights (raster only)");
    // The acceleration structures hold the scene as loaded (no skinning or morphing):
    // a posed frame drawn by rays would silently show the bind pose.
    if (!rt_refusal_.empty())
        throw GpuError("the ray tracer builds its structures from the stored vertices, but " +
                       rt_refusal_ +
                       " moves in its default pose (skin or default morph weights): raster only");
    if (settings.pose)
        throw GpuError("the ray tracer draws the scene as loaded (bind pose): posed frames "
                       "(--animation/--time) are raster only");
    // The shadow-error view compares with the rasterizer's cascades at this camera:
    // its shadow view is drawn first (cascades and frame constants in that slot).
    const std::uint32_t raster_slot = next_slot_;
    if (settings.view == DebugView::ShadowError) {
        RenderSettings raster = settings;
        raster.renderer = RendererKind::Raster;
        raster.view = DebugView::Shadow;
        render(raster, nullptr);
    }
    // Its descriptor set is rewritten per frame: no earlier frame may be in flight.
    for (auto& s : slots_) wait_slot(*s);
    if (!rt_views_)
        rt_views_ = std::make_unique<RtViewPass>(context, *resources, bindless->layout());
    const std::uint32_t index = next_slot_;
    next_slot_ = (next_slot_ + 1) % kFramesInFlight;
    FrameSlot& slot = *slots_[index];
    FrameStats stats;
    const VkAccelerationStructureKHR tlas = acceleration->tlas();
    if (tlas == VK_NULL_HANDLE) { // nothing with triangles: every ray misses
        if (rgba) {
            rgba->resize(std::size_t(settings.width) * settings.height * 4);
            const std::uint8_t c[4] = {srgb_byte(settings.clear_color.r),
                                       srgb_byte(settings.clear_color.g),
                                       srgb_byte(settings.clear_color.b), 255};
            for (std::size_t i = 0; i < rgba->size(); ++i) (*rgba)[i] = c[i % 4];
        }
        return stats;
    }
    const CameraView camera =
        resolve_camera(settings.camera, lighting_, float(settings.width) / float(settings.height));
    RayTracedFrame f;
    f.bindless = bindless->set();
    f.tlas = tlas;
    f.materials = scene->materials().buffer();
    f.material_extras = scene->materials().extras_buffer();
    f.width = settings.width;
    f.height = settings.height;
    f.push.inv_view_proj = glm::inverse(camera.proj * camera.view);
    f.push.geometries = acceleration->geometry_records();
    f.push.view = static_cast<std::uint32_t>(settings.view);
    f.push.texture_lod = settings.texture_lod;
    f.push.clear_color = settings.clear_color;
    f.frame_data = resources->get(slots_[raster_slot]->frame_data).buffer.get();
    f.shadow_map = shadows_.descriptor();
    const MainSun sun = main_sun(lighting_, settings);
    f.push.sun = glm::vec4(-sun.direction, std::max(settings.sun_angular_radius, 0.0f));
    // As the rasterizer: no sun or no shadows, and only the facing rule remains.
    f.push.shadow_rays = sun.present && settings.shadows ? std::max(settings.shadow_rays, 1u) : 0u;
    f.push.ao_rays = settings.ao_rays;
    const float diagonal = lighting_.bounds.valid() ? glm::length(lighting_.bounds.extent()) : 1.0f;
    f.push.ao_radius = settings.ao_radius > 0.0f ? settings.ao_radius : 0.05f * diagonal;

    VkCommandBuffer cmd = slot.recorder.begin();
    const bool timed = context.info().timestamps;
    if (timed) {
        vkCmdResetQueryPool(cmd, slot.timestamps.get(), 0, 2);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_NONE, slot.timestamps.get(), 0);
    }
    rt_views_->record(cmd, f);
    if (timed)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, slot.timestamps.get(), 1);
    slot.submission = slot.recorder.submit(*resources);
    slot.has_results = false; // its queries hold this frame's two timestamps only
    wait_slot(slot);
    if (timed) {
        std::uint64_t ts[2] = {};
        vk_check(vkGetQueryPoolResults(context.device(), slot.timestamps.get(), 0, 2, sizeof(ts),
                                       ts, sizeof(std::uint64_t),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                 "vkGetQueryPoolResults(rt timestamps)");
        stats.gpu_ms = double(ts[1] - ts[0]) * context.info().timestamp_period_ns * 1e-6;
        stats.passes.push_back({"rays", stats.gpu_ms});
    }
    if (rgba) rt_views_->read(*rgba);
    resources->collect_garbage();
    return stats;
}

} // namespace sherpa::gpu
