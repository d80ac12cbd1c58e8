#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/resources.h>

#include <algorithm>

namespace sherpa::gpu {

ResourceManager::ResourceManager(Context& context) : context_(context) {
    VkSemaphoreTypeCreateInfo type =
        vk_init<VkSemaphoreTypeCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO);
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    type.initialValue = 0;
    VkSemaphoreCreateInfo ci =
        vk_init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    ci.pNext = &type;
    VkSemaphore s = VK_NULL_HANDLE;
    vk_check(vkCreateSemaphore(context_.device(), &ci, nullptr, &s), "vkCreateSemaphore(timeline)");
    timeline_ = UniqueSemaphore(context_.device(), s);
}

ResourceManager::~ResourceManager() {
    // Owners destroy their handles first; whatever is left (pending or live) goes
    // with the pools once the GPU is idle.
    vkDeviceWaitIdle(context_.device());
    retired_.clear();
}

UniqueMemory ResourceManager::allocate(const VkMemoryRequirements& req, MemoryUsage usage,
                                       bool device_address, VkDeviceSize& allocated) {
    std::uint32_t type = 0;
    switch (usage) {
    case MemoryUsage::DeviceLocal:
        type = context_.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        break;
    case MemoryUsage::Upload:
        type = context_.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                            VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        break;
    case MemoryUsage::Readback:
        // Cached memory makes CPU reads fast; coherent keeps us free of invalidates.
        if (!context_.find_memory_type(req.memoryTypeBits,
                                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                           VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                                           VK_MEMORY_PROPERTY_HOST_CACHED_BIT,
                                       type))
            type =
                context_.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                             VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        break;
    }
    VkMemoryAllocateFlagsInfo flags =
        vk_init<VkMemoryAllocateFlagsInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO);
    flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo ai = vk_init<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    ai.pNext = device_address ? &flags : nullptr;
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = type;
    VkDeviceMemory mem = VK_NULL_HANDLE;
    vk_check(vkAllocateMemory(context_.device(), &ai, nullptr, &mem), "vkAllocateMemory");
    allocated = req.size;
    return UniqueMemory(context_.device(), mem);
}

BufferHandle ResourceManager::create_buffer(const BufferDesc& desc) {
    if (desc.size == 0) throw GpuError("buffer '" + desc.name + "' has size 0");
    VkDevice device = context_.device();
    Buffer b;
    VkBufferCreateInfo ci = vk_init<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    ci.size = desc.size;
    ci.usage = desc.usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer raw = VK_NULL_HANDLE;
    vk_check(vkCreateBuffer(device, &ci, nullptr, &raw), "vkCreateBuffer");
    b.buffer = UniqueBuffer(device, raw);
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, raw, &req);
    const bool bda = (desc.usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
    b.memory = allocate(req, desc.memory, bda, b.allocation_size);
    vk_check(vkBindBufferMemory(device, raw, b.memory.get(), 0), "vkBindBufferMemory");
    b.size = desc.size;
    if (bda) {
        VkBufferDeviceAddressInfo ai =
            vk_init<VkBufferDeviceAddressInfo>(VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO);
        ai.buffer = raw;
        b.address = vkGetBufferDeviceAddress(device, &ai);
    }
    if (desc.memory != MemoryUsage::DeviceLocal)
        vk_check(vkMapMemory(device, b.memory.get(), 0, VK_WHOLE_SIZE, 0, &b.mapped),
                 "vkMapMemory");
    context_.set_debug_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(raw),
                            desc.name.c_str());
    return buffers_.insert(std::move(b));
}

ImageHandle ResourceManager::create_image(const ImageDesc& desc) {
    VkDevice device = context_.device();
    Image img;
    img.desc = desc;
    VkImageCreateInfo ci = vk_init<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    ci.imageType = VK_IMAGE_TYPE_2D;
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
    img.memory = allocate(req, MemoryUsage::DeviceLocal, false, img.allocation_size);
    vk_check(vkBindImageMemory(device, raw, img.memory.get(), 0), "vkBindImageMemory");

    auto make_view = [&](VkImageViewType type, std::uint32_t base_layer, std::uint32_t layers) {
        VkImageViewCreateInfo vi =
            vk_init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        vi.image = raw;
        vi.viewType = type;
        vi.format = desc.format;
        vi.subresourceRange = {desc.aspect, 0, desc.mip_levels, base_layer, layers};
        VkImageView v = VK_NULL_HANDLE;
        vk_check(vkCreateImageView(device, &vi, nullptr, &v), "vkCreateImageView");
        return UniqueImageView(device, v);
    };
    img.view = make_view(desc.view_type, 0, desc.layers);
    if (desc.layer_views)
        for (std::uint32_t l = 0; l < desc.layers; ++l)
            img.layer_views.push_back(make_view(VK_IMAGE_VIEW_TYPE_2D, l, 1));
    context_.set_debug_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(raw),
                            desc.name.c_str());
    return images_.insert(std::move(img));
}

SamplerHandle ResourceManager::create_sampler(const VkSamplerCreateInfo& info) {
    VkSampler s = VK_NULL_HANDLE;
    vk_check(vkCreateSampler(context_.device(), &info, nullptr, &s), "vkCreateSampler");
    return samplers_.insert(UniqueSampler(context_.device(), s));
}

ResourceManager::Retired& ResourceManager::retire_list() {
    // The submission being recorded (not yet submitted) gets value submitted_ + 1.
    const std::uint64_t after = submitted_ + 1;
    if (retired_.empty() || retired_.back().after != after)
        retired_.push_back(Retired{after, {}, {}, {}});
    return retired_.back();
}

void ResourceManager::destroy(BufferHandle& h) {
    if (!h.valid()) return;
    retire_list().buffers.push_back(buffers_.take(h));
    h = {};
}

void ResourceManager::destroy(ImageHandle& h) {
    if (!h.valid()) return;
    retire_list().images.push_back(images_.take(h));
    h = {};
}

void ResourceManager::destroy(SamplerHandle& h) {
    if (!h.valid()) return;
    retire_list().samplers.push_back(samplers_.take(h));
    h = {};
}

std::uint64_t ResourceManager::completed_submission() const {
    std::uint64_t value = 0;
    vk_check(vkGetSemaphoreCounterValue(context_.device(), timeline_.get(), &value),
             "vkGetSemaphoreCounterValue");
    return value;
}

void ResourceManager::wait_for(std::uint64_t value) const {
    VkSemaphore s = timeline_.get();
    VkSemaphoreWaitInfo wi = vk_init<VkSemaphoreWaitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO);
    wi.semaphoreCount = 1;
    wi.pSemaphores = &s;
    wi.pValues = &value;
    vk_check(vkWaitSemaphores(context_.device(), &wi, UINT64_MAX), "vkWaitSemaphores");
}

void ResourceManager::collect_garbage() {
    if (retired_.empty()) return;
    const std::uint64_t done = completed_submission();
    auto keep = std::find_if(retired_.begin(), retired_.end(),
                             [&](const Retired& r) { return r.after > done; });
    retired_.erase(retired_.begin(), keep);
}

void ResourceManager::flush() {
    vkDeviceWaitIdle(context_.device());
    retired_.clear();
}

ResourceCounts ResourceManager::counts() const {
    ResourceCounts c;
    c.buffers = buffers_.live();
    c.images = images_.live();
    c.samplers = samplers_.live();
    for (const Retired& r : retired_)
        c.pending_destruction += r.buffers.size() + r.images.size() + r.samplers.size();
    return c;
}

} // namespace sherpa::gpu
