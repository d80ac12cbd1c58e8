#pragma once
// The path tracer (render --renderer rt --view lit, docs/path_tracer.md): the ray-tracing
// pipeline of shaders/pt.*, its descriptor set, the running per-pixel sums it adds
// samples to (RGBA32F radiance and coverage, R32F squared luminance) and the tone-mapped
// image it shows (RGBA8, sRGB-encoded bytes, as the debug views' RtViewPass), read back
// as the rasterizer's offscreen target is. The sums stay on the GPU between frames:
// the Renderer decides when they start over (renderer_path.cpp).
#include "rt_pipeline.h"

#include <sherpa/gpu/resources.h>
#include <sherpa/render/emissive_lights.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/path_trace.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace sherpa::render {

struct PathTracedFrame {
    VkDescriptorSet bindless = VK_NULL_HANDLE;
    VkAccelerationStructureKHR tlas = VK_NULL_HANDLE;
    VkBuffer materials = VK_NULL_HANDLE, material_extras = VK_NULL_HANDLE;
    VkBuffer material_extensions = VK_NULL_HANDLE; // none where no material uses one
    VkBuffer frame_data = VK_NULL_HANDLE; // GPUFrameData: lights, sun, environment, display
    VkDescriptorImageInfo environment{};  // the specular cube; no view: no environment
    std::uint32_t width = 0, height = 0;
    std::uint32_t first_sample = 0, samples = 0; // first_sample 0: the sums start over
    GPUPathPushConstants push{};                 // first_sample, samples, env_size: set here
    bool light_sampling = true;                  // the emissive triangles' light list
    bool one_light_ray = true;                   // PathTraceSettings::one_light_ray
};

class PathTracePass {
public:
    // Samples per pixel in one launch: a long accumulation is split into launches so that
    // no single dispatch runs long (a GPU's watchdog, an editor's frame).
    static constexpr std::uint32_t kSamplesPerLaunch = 16;

    PathTracePass(gpu::Context& context, gpu::ResourceManager& resources,
                  VkDescriptorSetLayout bindless_layout);
    ~PathTracePass();
    PathTracePass(const PathTracePass&) = delete;
    PathTracePass& operator=(const PathTracePass&) = delete;

    // The environment's sampling distribution (empty: BRDF sampling only), uploaded.
    void set_distribution(const EnvironmentDistribution& distribution);
    // The emissive triangles' light list (empty: none), uploaded.
    void set_lights(const EmissiveLights& lights);
    // Records the launches and, with `readback`, the copy of the shown image. The
    // previous frame of this pass must have completed (its set is rewritten). Without
    // `readback` the image stays in GENERAL layout for sampled reads.
    void record(VkCommandBuffer cmd, const PathTracedFrame& frame, bool readback = true);
    VkImageView view() const { return resources_.images().get(shown_).view.get(); }
    // After the submission completed: RGBA8 rows, top first (sRGB-encoded bytes).
    void read(std::vector<std::uint8_t>& rgba) const;
    // Copies the sums into a host buffer; after that submission, read_sums() has them.
    void record_sums_readback(VkCommandBuffer cmd);
    void read_sums(PathTraceImage& image) const;
    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

private:
    void ensure_targets(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height);
    void write_set(const PathTracedFrame& f);
    void destroy_targets();

    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    gpu::UniqueDescriptorSetLayout set_layout_;
    gpu::UniqueDescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    gpu::UniquePipelineLayout layout_;
    std::unique_ptr<RayPipeline> pipeline_;
    gpu::ImageHandle shown_, sums_, moments_;
    gpu::BufferHandle readback_, sums_readback_, distribution_, lights_;
    float light_inv_power_ = 0.0f;
    glm::uvec2 distribution_size_{0u, 0u};
    std::uint32_t width_ = 0, height_ = 0;
};

} // namespace sherpa::render
