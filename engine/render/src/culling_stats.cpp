// Culling statistics of a completed frame: the CPU path's counts as recorded; on
// the GPU path the visible counts and triangles come from the indirect commands
// read back (no CPU test), the GPU time from timestamps around each dispatch, and
// in check mode the differences against the CPU test.
#include "passes.h"

#include <sherpa/gpu/gpu_error.h>

#include <cstring>

namespace sherpa::render {

void CullingPass::read_stats(FrameSlot& slot, const GpuScene* scene, FrameStats& out) {
    out.prepass = slot.prepass;
    out.culling.clear();
    const FrameCulling& fc = slot.culling;
    if (fc.count == 0) return;
    const bool gpu = fc.path == CullPath::Gpu;
    const std::uint32_t passes = fc.count;
    std::uint64_t ts[2 * kMaxCullPasses] = {};
    bool have_ts = false;
    if (gpu && slot.cull_timestamps)
        have_ts =
            vkGetQueryPoolResults(context_.device(), slot.cull_timestamps.get(), 0, 2 * passes,
                                  sizeof(ts), ts, sizeof(std::uint64_t),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS;
    const auto* bytes =
        gpu ? static_cast<const std::uint8_t*>(resources_.get(slot.cull_readback).mapped) : nullptr;
    for (std::uint32_t p = 0; p < passes; ++p) {
        const PassCull& pc = fc.views[p];
        scene::CullStats st = pc.stats; // draws and CPU-path triangles tallied while recording
        if (gpu) {
            const GpuCuller& culler = *pc.gpu;
            std::vector<VkDrawIndexedIndirectCommand> draws(culler.batch_count());
            std::memcpy(draws.data(), bytes + pc.readback,
                        draws.size() * sizeof(VkDrawIndexedIndirectCommand));
            // Batches of lines and points meshes draw no triangles.
            std::vector<bool> triangle_batch(draws.size(), true);
            for (std::size_t g = 0; g < scene->groups().size(); ++g)
                if (const std::uint32_t b = culling_->group_batch[g]; b < draws.size())
                    triangle_batch[b] =
                        is_triangle_mesh(scene->meshes()[scene->groups()[g].mesh].flags);
            std::uint64_t visible = 0, triangles = 0;
            for (std::size_t b = 0; b < draws.size(); ++b) {
                visible += draws[b].instanceCount;
                if (triangle_batch[b])
                    triangles += std::uint64_t{draws[b].instanceCount} * (draws[b].indexCount / 3);
            }
            if (p == 0) {
                // Blended instances: CPU-tested, drawn one by one (tallied already).
                // A frame with passes had a scene.
                const auto& groups = scene->groups();
                if (!pc.group_visible.empty())
                    for (std::size_t g = 0; g < groups.size(); ++g)
                        if (groups[g].alpha == scene::AlphaMode::Blend)
                            visible += pc.group_visible[g];
                if (slot.prepass.draw_calls) out.prepass.triangles += triangles;
            }
            st.visible = visible;
            st.culled = st.tested - visible;
            st.triangles += triangles;
            if (have_ts)
                st.gpu_ms =
                    double(ts[2 * p + 1] - ts[2 * p]) * context_.info().timestamp_period_ns * 1e-6;
            if (fc.check && pc.cpu_tested) {
                std::vector<std::uint32_t> flags(culler.object_count());
                std::memcpy(flags.data(),
                            bytes + pc.readback +
                                draws.size() * sizeof(VkDrawIndexedIndirectCommand),
                            flags.size() * sizeof(std::uint32_t));
                std::int64_t differences = 0;
                for (std::size_t k = 0; k < flags.size(); ++k)
                    differences +=
                        (flags[k] != 0) != (pc.visible[culler.object_instances()[k]] != 0) ? 1 : 0;
                st.cpu_gpu_differences = differences;
            }
        }
        out.culling.push_back(std::move(st));
    }
    if (passes > 1)
        cascade_stats_.assign(out.culling.begin() + 1, out.culling.end());
    else
        out.culling.insert(out.culling.end(), cascade_stats_.begin(), cascade_stats_.end());
    if (!slot.history_pushed) {
        history_.push(CullFrame{fc.path, out.culling, passes > 1});
        slot.history_pushed = true;
    }
}

} // namespace sherpa::render
