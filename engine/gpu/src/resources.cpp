#include "memory.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

ResourceManager::ResourceManager(Context& context)
    : context_(context), timeline_(context.device()), images_(context, timeline_) {}

ResourceManager::~ResourceManager() {
    // Owners destroy their handles first; whatever is left (pending or live) goes
    // with the pools once the GPU is idle.
    vkDeviceWaitIdle(context_.device());
    retired_buffers_.clear();
    images_.clear_retired();
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
    b.memory = allocate_memory(context_, req, desc.memory, bda, b.allocation_size);
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

void ResourceManager::destroy(BufferHandle& h) {
    if (!h.valid()) return;
    // The submission being recorded (not yet submitted) gets the next timeline value.
    retired_buffers_.retire(timeline_.last_submission() + 1, buffers_.take(h));
    h = {};
}

void ResourceManager::collect_garbage() {
    if (retired_buffers_.size() + images_.pending() == 0) return;
    const std::uint64_t done = timeline_.completed_submission();
    retired_buffers_.release(done);
    images_.release(done);
}

void ResourceManager::flush() {
    vkDeviceWaitIdle(context_.device());
    retired_buffers_.clear();
    images_.clear_retired();
}

ResourceCounts ResourceManager::counts() const {
    ResourceCounts c;
    c.buffers = buffers_.live();
    c.images = images_.images_.live();
    c.samplers = images_.samplers_.live();
    c.pending_destruction = retired_buffers_.size() + images_.pending();
    return c;
}

std::uint64_t ResourceManager::stale_handle_uses() const {
    return buffers_.stale_uses() + images_.images_.stale_uses() + images_.samplers_.stale_uses();
}

} // namespace sherpa::gpu
