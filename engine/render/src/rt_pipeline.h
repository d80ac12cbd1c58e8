#pragma once
// A ray-tracing pipeline of one ray-generation shader, one miss shader and one
// triangle hit group (closest hit + any hit), with its shader binding table: what the
// ray-traced debug views (rt_view_pass.h) and the path tracer (path_trace_pass.h) each
// trace with. Private to the render layer.
#include <sherpa/gpu/acceleration_structure.h>
#include <sherpa/gpu/resources.h>

#include <cstdint>
#include <span>

namespace sherpa::render {

struct RayShaders {
    std::span<const std::uint32_t> raygen, miss, closest_hit, any_hit; // SPIR-V
};

class RayPipeline {
public:
    RayPipeline(gpu::Context& context, gpu::ResourceManager& resources, VkPipelineLayout layout,
                const RayShaders& shaders);
    ~RayPipeline();
    RayPipeline(const RayPipeline&) = delete;
    RayPipeline& operator=(const RayPipeline&) = delete;

    void bind(VkCommandBuffer cmd) const;
    void trace(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const;

private:
    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    gpu::RayTracingFunctions fn_;
    gpu::UniquePipeline pipeline_;
    gpu::BufferHandle sbt_;
    VkStridedDeviceAddressRegionKHR raygen_{}, miss_{}, hit_{}, callable_{};
};

} // namespace sherpa::render
