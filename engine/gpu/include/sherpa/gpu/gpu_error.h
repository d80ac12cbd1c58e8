#pragma once
// Errors of the GPU layer. Vulkan failures and misuse (stale handles, missing
// device features) throw GpuError; callers at the top (CLI, editor) report them.
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace sherpa::gpu {

class GpuError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

std::string to_string(VkResult r);

// Throws GpuError naming `what` and the result unless `r` is VK_SUCCESS.
void vk_check(VkResult r, const char* what);

// A zeroed Vulkan structure with its sType set (avoids -Wmissing-field-initializers
// on the usual `T x{sType}` idiom).
template <typename T> T vk_init(VkStructureType type) {
    T t{};
    t.sType = type;
    return t;
}

} // namespace sherpa::gpu
