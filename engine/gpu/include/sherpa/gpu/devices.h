#pragma once
// The physical devices an instance sees, for listing (the editor's About box) and
// for Context's choice (lavapipe first, SHERPA_DEVICE to pick another).
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace sherpa::gpu {

struct DeviceSummary {
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    std::string name;
    std::uint32_t api_version = 0;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
};

// Every physical device of `instance`, in the loader's order.
std::vector<DeviceSummary> enumerate_devices(VkInstance instance);
// "NAME (Vulkan MAJOR.MINOR.PATCH)".
std::string describe(const DeviceSummary& device);

} // namespace sherpa::gpu
