#include <sherpa/gpu/bindless.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/gpu/vk_helpers.h>

#include <array>

namespace sherpa::gpu {

BindlessTable::BindlessTable(ResourceManager& resources) : resources_(resources) {
    VkDevice device = resources.context().device();
    // Hit shaders sample materials too where the device ray traces.
    const VkShaderStageFlags stages = resources.context().info().ray_tracing_enabled
                                          ? VK_SHADER_STAGE_FRAGMENT_BIT |
                                                VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR |
                                                VK_SHADER_STAGE_ANY_HIT_BIT_KHR
                                          : VkShaderStageFlags(VK_SHADER_STAGE_FRAGMENT_BIT);
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCapacity,
                                         stages, nullptr};
    // Slots are written while earlier frames that do not read them are in flight.
    const VkDescriptorBindingFlags flags = VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT |
                                           VK_DESCRIPTOR_BINDING_VARIABLE_DESCRIPTOR_COUNT_BIT |
                                           VK_DESCRIPTOR_BINDING_UPDATE_AFTER_BIND_BIT |
                                           VK_DESCRIPTOR_BINDING_UPDATE_UNUSED_WHILE_PENDING_BIT;
    auto flags_info = vk_init<VkDescriptorSetLayoutBindingFlagsCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO);
    flags_info.bindingCount = 1;
    flags_info.pBindingFlags = &flags;
    layout_ = create_descriptor_set_layout(
        device, {&binding, 1}, "vkCreateDescriptorSetLayout(bindless)",
        VK_DESCRIPTOR_SET_LAYOUT_CREATE_UPDATE_AFTER_BIND_POOL_BIT, &flags_info);
    const VkDescriptorSetLayout layout = layout_.get();
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCapacity};
    pool_ = create_descriptor_pool(device, 1, {&size, 1}, "vkCreateDescriptorPool(bindless)",
                                   VK_DESCRIPTOR_POOL_CREATE_UPDATE_AFTER_BIND_BIT);
    const VkDescriptorPool pool = pool_.get();

    const std::uint32_t count = kCapacity;
    auto vci = vk_init<VkDescriptorSetVariableDescriptorCountAllocateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO);
    vci.descriptorSetCount = 1;
    vci.pDescriptorCounts = &count;
    auto ai = vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    ai.pNext = &vci;
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    vk_check(vkAllocateDescriptorSets(device, &ai, &set_), "vkAllocateDescriptorSets");
    create_defaults();
}

BindlessTable::~BindlessTable() {
    for (ImageHandle& h : defaults_) resources_.images().destroy(h);
    resources_.images().destroy(default_sampler_);
}

void BindlessTable::create_defaults() {
    auto si = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = si.minFilter = VK_FILTER_NEAREST;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    default_sampler_ = resources_.images().create_sampler(si);
    // Slot order is fixed: kWhiteTexture, kFlatNormalTexture, kBlackTexture, kCheckerTexture.
    const std::uint8_t texels[3][4] = {{255, 255, 255, 255}, {128, 128, 255, 255}, {0, 0, 0, 255}};
    std::vector<std::uint8_t> checker(std::size_t(kCheckerTextureSize) * kCheckerTextureSize * 4);
    for (std::uint32_t y = 0; y < kCheckerTextureSize; ++y)
        for (std::uint32_t x = 0; x < kCheckerTextureSize; ++x) {
            const std::uint8_t on = (x + y) % 2 == 0 ? 255 : 0; // magenta or black
            std::uint8_t* t = checker.data() + (std::size_t(y) * kCheckerTextureSize + x) * 4;
            t[0] = on, t[1] = 0, t[2] = on, t[3] = 255;
        }
    const char* names[kDefaultTextureCount] = {"default white", "default flat normal",
                                               "default black", "missing-texture checker"};
    UploadBatch batch(resources_);
    for (std::uint32_t i = 0; i < kDefaultTextureCount; ++i) {
        ImageDesc d;
        d.format = VK_FORMAT_R8G8B8A8_UNORM;
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        d.name = names[i];
        const bool is_checker = i == kCheckerTexture;
        if (is_checker) d.width = d.height = kCheckerTextureSize;
        defaults_[i] = resources_.images().create(d);
        if (is_checker)
            batch.upload_image(defaults_[i], checker.data(), checker.size());
        else
            batch.upload_image(defaults_[i], texels[i], 4);
    }
    batch.submit_and_wait();
    for (std::uint32_t i = 0; i < kDefaultTextureCount; ++i)
        add(resources_.images().get(defaults_[i]).view.get(),
            resources_.images().get(default_sampler_));
}

void BindlessTable::write(std::uint32_t binding, std::uint32_t slot, VkImageView view,
                          VkSampler sampler, VkImageLayout layout) {
    VkDescriptorImageInfo ii{sampler, view, layout};
    auto w = vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w.dstSet = set_;
    w.dstBinding = binding;
    w.dstArrayElement = slot;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &ii;
    vkUpdateDescriptorSets(resources_.context().device(), 1, &w, 0, nullptr);
}

std::uint32_t BindlessTable::add(VkImageView view, VkSampler sampler) {
    std::uint32_t slot;
    if (!free_.empty()) {
        slot = free_.back();
        free_.pop_back();
    } else {
        if (next_ >= kCapacity) throw GpuError("bindless texture table is full");
        slot = next_++;
    }
    write(0, slot, view, sampler, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    return slot;
}

void BindlessTable::remove(std::uint32_t slot) {
    // The descriptor stays as it is (partially bound): nothing indexes it any more.
    if (slot >= kDefaultTextureCount) free_.push_back(slot);
}

} // namespace sherpa::gpu
