#pragma once
// The ray-traced debug views (render --renderer rt): one ray-tracing pipeline
// (shaders/rt.rgen, rt.rmiss, and one hit group of rt.rchit + rt.rahit, rt_pipeline.h),
// its descriptor set and the storage image the rays write, read back
// as the rasterizer's offscreen target is. Private to the render layer; the
// Renderer drives it (renderer_rt.cpp) with the scene's acceleration structures.
#include "rt_pipeline.h"

#include <sherpa/gpu/acceleration_structure.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/render/gpu_structs.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace sherpa::render {

struct RayTracedFrame {
    VkDescriptorSet bindless = VK_NULL_HANDLE;
    VkAccelerationStructureKHR tlas = VK_NULL_HANDLE;
    VkBuffer materials = VK_NULL_HANDLE, material_extras = VK_NULL_HANDLE;
    // GPUFrameData of the rasterizer's frame of this camera and its shadow cascades:
    // read by the shadow-error view, bound (whatever they hold) for every view.
    VkBuffer frame_data = VK_NULL_HANDLE;
    VkDescriptorImageInfo shadow_map{};
    std::uint32_t width = 0, height = 0;
    GPURayPushConstants push{};
};

class RtViewPass {
public:
    RtViewPass(gpu::Context& context, gpu::ResourceManager& resources,
               VkDescriptorSetLayout bindless_layout);
    ~RtViewPass();
    RtViewPass(const RtViewPass&) = delete;
    RtViewPass& operator=(const RtViewPass&) = delete;

    // Records the rays and the copy of the image into the readback buffer. The
    // previous frame of this pass must have completed (its set is rewritten).
    // Without `readback` the image stays in GENERAL layout for sampled reads by
    // compute and fragment shaders (the comparison pass, a presented RT frame).
    void record(VkCommandBuffer cmd, const RayTracedFrame& frame, bool readback = true);
    // The image (RGBA8 UNORM holding sRGB-encoded bytes) of the last frame recorded.
    VkImageView view() const { return resources_.images().get(target_).view.get(); }
    // After the submission completed: RGBA8 rows, top first (sRGB-encoded bytes).
    void read(std::vector<std::uint8_t>& rgba) const;

private:
    void ensure_target(std::uint32_t width, std::uint32_t height);

    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    gpu::UniqueDescriptorSetLayout set_layout_;
    gpu::UniqueDescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    gpu::UniquePipelineLayout layout_;
    std::unique_ptr<RayPipeline> pipeline_;
    gpu::ImageHandle target_;
    gpu::BufferHandle readback_;
    std::uint32_t width_ = 0, height_ = 0;
};

} // namespace sherpa::render
