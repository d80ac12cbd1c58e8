#include "path_trace_pass.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "pt_rahit.h"
#include "pt_rchit.h"
#include "pt_rgen.h"
#include "pt_rmiss.h"

namespace sherpa::render {
namespace {

constexpr VkShaderStageFlags kRaygen = VK_SHADER_STAGE_RAYGEN_BIT_KHR;
constexpr VkShaderStageFlags kHitStages =
    VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
constexpr VkShaderStageFlags kAllStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR | kHitStages;
constexpr std::uint32_t kBindings = 11;

// Copies `image` (GENERAL, written by the launches) into `buffer` at `offset` through
// TRANSFER_SRC_OPTIMAL, and back to GENERAL for the next launches.
void copy_to_buffer(VkCommandBuffer cmd, VkImage image, VkBuffer buffer, VkDeviceSize offset,
                    std::uint32_t width, std::uint32_t height) {
    gpu::ImageTransition t;
    t.image = image;
    t.from = VK_IMAGE_LAYOUT_GENERAL;
    t.to = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    t.src_stage = VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;
    t.src_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    t.dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT;
    t.dst_access = VK_ACCESS_2_TRANSFER_READ_BIT;
    gpu::transition(cmd, t);
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    std::swap(t.from, t.to);
    t.src_stage = VK_PIPELINE_STAGE_2_COPY_BIT;
    t.src_access = VK_ACCESS_2_NONE;
    t.dst_stage = VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR |
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    t.dst_access = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    gpu::transition(cmd, t);
}

} // namespace

PathTracePass::PathTracePass(gpu::Context& context, gpu::ResourceManager& resources,
                             VkDescriptorSetLayout bindless_layout)
    : context_(context), resources_(resources) {
    VkDevice device = context.device();
    const VkDescriptorSetLayoutBinding bindings[kBindings] = {
        {0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1, kRaygen, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, kRaygen, nullptr}, // the shown image
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kHitStages, nullptr},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kHitStages, nullptr},
        {4, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kRaygen, nullptr},
        // The environment: partially bound, nothing there (and nothing read) without one.
        {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, kRaygen, nullptr},
        {6, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, kRaygen, nullptr},  // sums
        {7, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, kRaygen, nullptr},  // squared luminance
        {8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kRaygen, nullptr}, // distribution
        // The material extension blocks (material_ext.glsl): partially bound, nothing
        // there where no material uses an extension.
        {9, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kHitStages, nullptr},
        // The emissive triangles' light list: partially bound, nothing without one.
        {10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kRaygen, nullptr},
    };
    constexpr VkDescriptorBindingFlags kPartial = VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT;
    const VkDescriptorBindingFlags flags[kBindings] = {0, 0, 0,        0,        0,       kPartial,
                                                       0, 0, kPartial, kPartial, kPartial};
    auto flags_info = gpu::vk_init<VkDescriptorSetLayoutBindingFlagsCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO);
    flags_info.bindingCount = kBindings;
    flags_info.pBindingFlags = flags;
    set_layout_ = gpu::create_descriptor_set_layout(
        device, bindings, "vkCreateDescriptorSetLayout(path)", 0, &flags_info);
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 3},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 5},
                                          {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    pool_ = gpu::create_descriptor_pool(device, 1, sizes, "vkCreateDescriptorPool(path)");
    set_ = gpu::allocate_descriptor_set(device, pool_.get(), set_layout_.get(),
                                        "vkAllocateDescriptorSets(path)");
    const VkDescriptorSetLayout sets[] = {bindless_layout, set_layout_.get()};
    const VkPushConstantRange push{kAllStages, 0, sizeof(GPUPathPushConstants)};
    layout_ = gpu::create_pipeline_layout(device, sets, {&push, 1}, "vkCreatePipelineLayout(path)");
    pipeline_ = std::make_unique<RayPipeline>(
        context, resources, layout_.get(),
        RayShaders{spirv_pt_rgen, spirv_pt_rmiss, spirv_pt_rchit, spirv_pt_rahit});
}

PathTracePass::~PathTracePass() {
    destroy_targets();
    resources_.destroy(distribution_);
    resources_.destroy(lights_);
}

void PathTracePass::destroy_targets() {
    resources_.images().destroy(shown_);
    resources_.images().destroy(sums_);
    resources_.images().destroy(moments_);
    resources_.destroy(readback_);
    resources_.destroy(sums_readback_);
}

void PathTracePass::set_distribution(const EnvironmentDistribution& d) {
    resources_.destroy(distribution_);
    distribution_size_ = glm::uvec2(0u);
    if (d.empty()) return;
    const VkDeviceSize bytes = d.cdf.size() * sizeof(float);
    distribution_ =
        resources_.create_buffer({bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  gpu::MemoryUsage::Upload, "environment distribution"});
    std::memcpy(resources_.get(distribution_).mapped, d.cdf.data(), bytes);
    distribution_size_ = glm::uvec2(d.width, d.height);
}

void PathTracePass::set_lights(const EmissiveLights& lights) {
    resources_.destroy(lights_);
    light_inv_power_ = 0.0f;
    if (lights.triangles.empty()) return;
    const VkDeviceSize bytes = lights.triangles.size() * sizeof(EmissiveTriangle);
    lights_ = resources_.create_buffer({bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        gpu::MemoryUsage::Upload, "emissive triangles"});
    std::memcpy(resources_.get(lights_).mapped, lights.triangles.data(), bytes);
    light_inv_power_ = lights.inv_power;
}

// The images are made (and their sums start over) when the size changes; they stay in
// GENERAL layout for their whole life.
void PathTracePass::ensure_targets(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) {
    if (shown_.valid() && width == width_ && height == height_) return;
    destroy_targets();
    auto image = [&](VkFormat format, VkImageUsageFlags extra, const char* name) {
        gpu::ImageDesc d;
        d.format = format;
        d.width = width;
        d.height = height;
        d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | extra;
        d.name = name;
        return resources_.images().create(d);
    };
    shown_ = image(VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT, "path-traced image");
    sums_ = image(VK_FORMAT_R32G32B32A32_SFLOAT, 0, "path-traced sums");
    moments_ = image(VK_FORMAT_R32_SFLOAT, 0, "path-traced squared luminance");
    readback_ = resources_.create_buffer(
        {VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
         gpu::MemoryUsage::Readback, "path-traced image readback"});
    width_ = width;
    height_ = height;
    for (gpu::ImageHandle h : {shown_, sums_, moments_}) {
        gpu::ImageTransition t;
        t.image = resources_.images().get(h).image.get();
        t.to = VK_IMAGE_LAYOUT_GENERAL;
        t.dst_stage = VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;
        t.dst_access = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
        gpu::transition(cmd, t);
    }
}

void PathTracePass::write_set(const PathTracedFrame& f) {
    auto as_write = gpu::vk_init<VkWriteDescriptorSetAccelerationStructureKHR>(
        VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR);
    as_write.accelerationStructureCount = 1;
    as_write.pAccelerationStructures = &f.tlas;
    const gpu::ImagePool& images = resources_.images();
    const VkDescriptorImageInfo storage[] = {
        {VK_NULL_HANDLE, images.get(shown_).view.get(), VK_IMAGE_LAYOUT_GENERAL},
        {VK_NULL_HANDLE, images.get(sums_).view.get(), VK_IMAGE_LAYOUT_GENERAL},
        {VK_NULL_HANDLE, images.get(moments_).view.get(), VK_IMAGE_LAYOUT_GENERAL}};
    const VkDescriptorBufferInfo buffers[] = {{f.materials, 0, VK_WHOLE_SIZE},
                                              {f.material_extras, 0, VK_WHOLE_SIZE},
                                              {f.frame_data, 0, VK_WHOLE_SIZE}};
    std::array<VkWriteDescriptorSet, kBindings> writes{};
    std::uint32_t count = 0;
    auto add = [&](std::uint32_t binding, VkDescriptorType type) -> VkWriteDescriptorSet& {
        VkWriteDescriptorSet& w = writes[count++];
        w = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        w.dstSet = set_;
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = type;
        return w;
    };
    add(0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR).pNext = &as_write;
    add(1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).pImageInfo = &storage[0];
    add(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &buffers[0];
    add(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &buffers[1];
    add(4, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pBufferInfo = &buffers[2];
    if (f.environment.imageView != VK_NULL_HANDLE)
        add(5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).pImageInfo = &f.environment;
    add(6, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).pImageInfo = &storage[1];
    add(7, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE).pImageInfo = &storage[2];
    VkDescriptorBufferInfo distribution{};
    if (distribution_.valid()) {
        distribution = {resources_.get(distribution_).buffer.get(), 0, VK_WHOLE_SIZE};
        add(8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &distribution;
    }
    const VkDescriptorBufferInfo extensions{f.material_extensions, 0, VK_WHOLE_SIZE};
    if (f.material_extensions != VK_NULL_HANDLE)
        add(9, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &extensions;
    VkDescriptorBufferInfo lights{};
    if (lights_.valid()) {
        lights = {resources_.get(lights_).buffer.get(), 0, VK_WHOLE_SIZE};
        add(10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &lights;
    }
    vkUpdateDescriptorSets(context_.device(), count, writes.data(), 0, nullptr);
}

void PathTracePass::record(VkCommandBuffer cmd, const PathTracedFrame& f, bool readback) {
    ensure_targets(cmd, f.width, f.height);
    write_set(f);
    // The last frame's launches and copies (an earlier submission) before these.
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    pipeline_->bind(cmd);
    const VkDescriptorSet sets[] = {f.bindless, set_};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout_.get(), 0, 2, sets,
                            0, nullptr);
    GPUPathPushConstants push = f.push;
    push.env_size = f.environment.imageView != VK_NULL_HANDLE ? distribution_size_ : glm::uvec2(0u);
    push.light_inv_power = f.light_sampling ? light_inv_power_ : 0.0f;
    // At least one launch, so that the image is resolved even when no sample is added.
    std::uint32_t done = 0;
    do {
        push.first_sample = f.first_sample + done;
        push.samples =
            std::min(kSamplesPerLaunch, f.samples - done) | (f.one_light_ray ? 0u : kPathAllLights);
        vkCmdPushConstants(cmd, layout_.get(), kAllStages, 0, sizeof(push), &push);
        pipeline_->trace(cmd, f.width, f.height);
        done += push.samples & kPathSampleCount;
        gpu::memory_barrier(
            cmd, VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
            VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR |
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                VK_PIPELINE_STAGE_2_COPY_BIT,
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT);
    } while (done < f.samples);
    if (!readback) return;
    copy_to_buffer(cmd, resources_.images().get(shown_).image.get(),
                   resources_.get(readback_).buffer.get(), 0, f.width, f.height);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void PathTracePass::read(std::vector<std::uint8_t>& rgba) const {
    rgba.resize(std::size_t(width_) * height_ * 4);
    std::memcpy(rgba.data(), resources_.get(readback_).mapped, rgba.size());
}

void PathTracePass::record_sums_readback(VkCommandBuffer cmd) {
    if (!sums_.valid()) return;
    const VkDeviceSize pixels = VkDeviceSize(width_) * height_;
    if (!sums_readback_.valid())
        sums_readback_ =
            resources_.create_buffer({pixels * 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                      gpu::MemoryUsage::Readback, "path-traced sums readback"});
    const VkBuffer dst = resources_.get(sums_readback_).buffer.get();
    copy_to_buffer(cmd, resources_.images().get(sums_).image.get(), dst, 0, width_, height_);
    copy_to_buffer(cmd, resources_.images().get(moments_).image.get(), dst, pixels * 16, width_,
                   height_);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void PathTracePass::read_sums(PathTraceImage& image) const {
    image.width = width_;
    image.height = height_;
    const std::size_t pixels = std::size_t(width_) * height_;
    image.sums.assign(pixels * 4, 0.0f);
    image.moments.assign(pixels, 0.0f);
    if (!sums_readback_.valid()) return;
    const auto* bytes = static_cast<const std::uint8_t*>(resources_.get(sums_readback_).mapped);
    std::memcpy(image.sums.data(), bytes, pixels * 16);
    std::memcpy(image.moments.data(), bytes + pixels * 16, pixels * 4);
}

} // namespace sherpa::render
