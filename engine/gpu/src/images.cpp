// ImagePool: images with their views, and samplers (ResourceManager::images()).
#include "memory.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

ImagePool::ImagePool(Context& context, const SubmissionTimeline& timeline)
    : context_(context), timeline_(timeline) {}

ImageHandle ImagePool::create(const ImageDesc& desc) {
    VkDevice device = context_.device();
    Image img;
    img.desc = desc;
    VkImageCreateInfo ci = vk_init<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    ci.imageType = VK_IMAGE_TYPE_2D;
    if (desc.alias_format != VK_FORMAT_UNDEFINED) ci.flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
    if (desc.view_type == VK_IMAGE_VIEW_TYPE_CUBE) ci.flags |= VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
    ci.format = desc.format;
    ci.extent = {desc.width, desc.height, 1};
    ci.mipLevels = desc.mip_levels;
    ci.arrayLayers = desc.layers;
    ci.samples = VK_SAMPLE_COUNT_1_BIT;
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = desc.usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage raw = VK_NULL_HANDLE;
    vk_check(vkCreateImage(device, &ci, nullptr, &raw), "vkCreateImage");
    img.image = UniqueImage(device, raw);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, raw, &req);
    img.memory =
        allocate_memory(context_, req, MemoryUsage::DeviceLocal, false, img.allocation_size);
    vk_check(vkBindImageMemory(device, raw, img.memory.get(), 0), "vkBindImageMemory");

    auto make_view = [&](VkImageViewType type, std::uint32_t base_layer, std::uint32_t layers,
                         VkFormat format) {
        VkImageViewCreateInfo vi =
            vk_init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        vi.image = raw;
        vi.viewType = type;
        vi.format = format;
        vi.subresourceRange = {desc.aspect, 0, desc.mip_levels, base_layer, layers};
        VkImageView v = VK_NULL_HANDLE;
        vk_check(vkCreateImageView(device, &vi, nullptr, &v), "vkCreateImageView");
        return UniqueImageView(device, v);
    };
    img.view = make_view(desc.view_type, 0, desc.layers, desc.format);
    if (desc.layer_views)
        for (std::uint32_t l = 0; l < desc.layers; ++l)
            img.layer_views.push_back(make_view(VK_IMAGE_VIEW_TYPE_2D, l, 1, desc.format));
    if (desc.alias_format != VK_FORMAT_UNDEFINED)
        img.alias_view = make_view(desc.view_type, 0, desc.layers, desc.alias_format);
    context_.set_debug_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(raw),
                            desc.name.c_str());
    return images_.insert(std::move(img));
}

SamplerHandle ImagePool::create_sampler(const VkSamplerCreateInfo& info) {
    VkSampler s = VK_NULL_HANDLE;
    vk_check(vkCreateSampler(context_.device(), &info, nullptr, &s), "vkCreateSampler");
    return samplers_.insert(UniqueSampler(context_.device(), s));
}

// The submission being recorded (not yet submitted) gets the next timeline value.
void ImagePool::destroy(ImageHandle& h) {
    if (!h.valid()) return;
    retired_images_.retire(timeline_.last_submission() + 1, images_.take(h));
    h = {};
}

void ImagePool::destroy(SamplerHandle& h) {
    if (!h.valid()) return;
    retired_samplers_.retire(timeline_.last_submission() + 1, samplers_.take(h));
    h = {};
}

void ImagePool::release(std::uint64_t completed) {
    retired_images_.release(completed);
    retired_samplers_.release(completed);
}

void ImagePool::clear_retired() {
    retired_images_.clear();
    retired_samplers_.clear();
}

} // namespace sherpa::gpu
