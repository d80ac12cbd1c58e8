#pragma once
// Device memory for one resource: the memory type chosen from the device's
// properties (DeviceInfo::memory) by what the resource is for, one dedicated
// allocation. Private to the RHI: buffers (ResourceManager) and images (ImagePool).
#include <cstdint>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

// The first memory type among `type_bits` with all `properties`; false if none.
bool find_memory_type(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t type_bits,
                      VkMemoryPropertyFlags properties, std::uint32_t& index);

// Allocates for `req`; `allocated` receives the allocation's size. Throws GpuError
// when no memory type fits `usage`.
UniqueMemory allocate_memory(const Context& context, const VkMemoryRequirements& req,
                             MemoryUsage usage, bool device_address, VkDeviceSize& allocated);

} // namespace sherpa::gpu
