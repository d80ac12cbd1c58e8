#include "environment_passes.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

#include "ibl_downsample_comp.h"
#include "ibl_equirect_comp.h"
#include "ibl_lut_anisotropic_comp.h"
#include "ibl_lut_comp.h"
#include "ibl_prefilter_comp.h"

namespace sherpa::render {
namespace {
constexpr std::uint32_t kGroup = 8; // local_size_x/y of every ibl_*.comp
}

IblLayout::IblLayout(VkDevice device, std::uint32_t max_sets) : device_(device) {
    const VkDescriptorSetLayoutBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    };
    set_layout_ =
        gpu::create_descriptor_set_layout(device, bindings, "vkCreateDescriptorSetLayout(ibl)");
    const VkDescriptorSetLayout set_layout = set_layout_.get();
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(GPUIblPush)};
    layout_ = gpu::create_pipeline_layout(device, {&set_layout, 1}, {&push, 1},
                                          "vkCreatePipelineLayout(ibl)");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, max_sets},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, max_sets}};
    pool_ = gpu::create_descriptor_pool(device, max_sets, sizes, "vkCreateDescriptorPool(ibl)");
}

VkDescriptorSet IblLayout::bind(VkSampler sampler, VkImageView source, VkImageView destination) {
    const VkDescriptorSetLayout set_layout = set_layout_.get();
    auto ai =
        gpu::vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    ai.descriptorPool = pool_.get();
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &set_layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    gpu::vk_check(vkAllocateDescriptorSets(device_, &ai, &set), "vkAllocateDescriptorSets(ibl)");
    // Every image of the build stays in GENERAL: levels are written and read in turn.
    const VkDescriptorImageInfo src{sampler, source, VK_IMAGE_LAYOUT_GENERAL};
    const VkDescriptorImageInfo dst{VK_NULL_HANDLE, destination, VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet writes[2];
    std::uint32_t count = 0;
    if (source != VK_NULL_HANDLE) {
        writes[count] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[count].dstSet = set;
        writes[count].dstBinding = 0;
        writes[count].descriptorCount = 1;
        writes[count].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[count++].pImageInfo = &src;
    }
    writes[count] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[count].dstSet = set;
    writes[count].dstBinding = 1;
    writes[count].descriptorCount = 1;
    writes[count].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    writes[count++].pImageInfo = &dst;
    vkUpdateDescriptorSets(device_, count, writes, 0, nullptr);
    return set;
}

IblComputePass::IblComputePass(VkDevice device, VkPipelineLayout layout,
                               std::span<const std::uint32_t> code, const char* what,
                               const VkSpecializationInfo* constants)
    : layout_(layout) {
    const gpu::UniqueShaderModule module = gpu::create_shader_module(device, code, what);
    pipeline_ = gpu::create_compute_pipeline(device, layout, module.get(), what, constants);
}

void IblComputePass::dispatch(VkCommandBuffer cmd, VkDescriptorSet set, const GPUIblPush& push,
                              std::uint32_t layers) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    const std::uint32_t groups = (push.face_size + kGroup - 1) / kGroup;
    vkCmdDispatch(cmd, groups, groups, layers);
}

EquirectToCubePass::EquirectToCubePass(VkDevice device, VkPipelineLayout layout)
    : IblComputePass(device, layout, spirv_ibl_equirect_comp, "ibl_equirect.comp") {}

void EquirectToCubePass::record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t face_size,
                                float equirect_lod) const {
    GPUIblPush p;
    p.face_size = face_size;
    p.equirect_lod = equirect_lod;
    dispatch(cmd, set, p, 6);
}

CubeDownsamplePass::CubeDownsamplePass(VkDevice device, VkPipelineLayout layout)
    : IblComputePass(device, layout, spirv_ibl_downsample_comp, "ibl_downsample.comp") {}

void CubeDownsamplePass::record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t face_size,
                                std::uint32_t source_lod) const {
    GPUIblPush p;
    p.face_size = face_size;
    p.source_lod = source_lod;
    dispatch(cmd, set, p, 6);
}

namespace {
// DISTRIBUTION (constant_id 0 of ibl_prefilter.comp), one constant per lobe.
const VkSpecializationMapEntry kLobeEntry{0, 0, sizeof(std::uint32_t)};
const std::uint32_t kLobeValues[] = {0, 1, 2};
const VkSpecializationInfo kLobeConstants[] = {{1, &kLobeEntry, 4, &kLobeValues[0]},
                                               {1, &kLobeEntry, 4, &kLobeValues[1]},
                                               {1, &kLobeEntry, 4, &kLobeValues[2]}};
} // namespace

PrefilterPass::PrefilterPass(VkDevice device, VkPipelineLayout layout, Lobe lobe)
    : IblComputePass(device, layout, spirv_ibl_prefilter_comp, "ibl_prefilter.comp",
                     &kLobeConstants[static_cast<std::uint32_t>(lobe)]) {}

void PrefilterPass::record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t face_size,
                           float roughness, std::uint32_t samples, std::uint32_t source_size,
                           std::uint32_t source_levels) const {
    GPUIblPush p;
    p.face_size = face_size;
    p.roughness = roughness;
    p.samples = samples;
    p.source_size = float(source_size);
    p.source_levels = float(source_levels);
    dispatch(cmd, set, p, 6);
}

BrdfLutPass::BrdfLutPass(VkDevice device, VkPipelineLayout layout, bool anisotropic)
    : IblComputePass(device, layout,
                     anisotropic ? std::span<const std::uint32_t>(spirv_ibl_lut_anisotropic_comp)
                                 : std::span<const std::uint32_t>(spirv_ibl_lut_comp),
                     anisotropic ? "ibl_lut_anisotropic.comp" : "ibl_lut.comp") {}

void BrdfLutPass::record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t size,
                         std::uint32_t samples, std::uint32_t layers) const {
    GPUIblPush p;
    p.face_size = size;
    p.samples = samples;
    dispatch(cmd, set, p, layers);
}

gpu::UniqueImageView level_view(VkDevice device, VkImage image, std::uint32_t level,
                                std::uint32_t layers) {
    auto vi = gpu::vk_init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    vi.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, layers};
    VkImageView v = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateImageView(device, &vi, nullptr, &v), "vkCreateImageView(ibl level)");
    return gpu::UniqueImageView(device, v);
}

} // namespace sherpa::render
