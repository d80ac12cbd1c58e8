#include "memory.h"

#include <sherpa/gpu/gpu_error.h>

#include <string>

namespace sherpa::gpu {

bool find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t type_bits,
                      VkMemoryPropertyFlags properties, std::uint32_t& index) {
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((type_bits & (1u << i)) &&
            (memory.memoryTypes[i].propertyFlags & properties) == properties) {
            index = i;
            return true;
        }
    }
    return false;
}

namespace {

std::uint32_t memory_type(const DeviceInfo& info, std::uint32_t type_bits,
                          VkMemoryPropertyFlags properties) {
    std::uint32_t index = 0;
    if (!find_memory_type(info.memory, type_bits, properties, index))
        throw GpuError(info.name + ": no memory type with properties " +
                       std::to_string(properties));
    return index;
}

} // namespace

UniqueMemory allocate_memory(const Context& context, const VkMemoryRequirements& req,
                             MemoryUsage usage, bool device_address, VkDeviceSize& allocated) {
    const DeviceInfo& info = context.info();
    std::uint32_t type = 0;
    switch (usage) {
    case MemoryUsage::DeviceLocal:
        type = memory_type(info, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        break;
    case MemoryUsage::Upload:
        type =
            memory_type(info, req.memoryTypeBits,
                        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        break;
    case MemoryUsage::Readback:
        // Cached memory makes CPU reads fast; coherent keeps us free of invalidates.
        if (!find_memory_type(info.memory, req.memoryTypeBits,
                              VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                  VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                                  VK_MEMORY_PROPERTY_HOST_CACHED_BIT,
                              type))
            type = memory_type(info, req.memoryTypeBits,
                               VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
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
    vk_check(vkAllocateMemory(context.device(), &ai, nullptr, &mem), "vkAllocateMemory");
    allocated = req.size;
    return UniqueMemory(context.device(), mem);
}

} // namespace sherpa::gpu
