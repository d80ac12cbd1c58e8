// Physical devices: enumeration (also what the editor's About box lists) and the
// Context's choice among them.
#include "device_features.h"

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/devices.h>

#include <cstdlib>

namespace sherpa::gpu {

namespace {

std::string env_or(const char* name, std::string fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : fallback;
}

} // namespace

std::vector<DeviceSummary> enumerate_devices(VkInstance instance) {
    std::uint32_t n = 0;
    vkEnumeratePhysicalDevices(instance, &n, nullptr);
    std::vector<VkPhysicalDevice> handles(n);
    vkEnumeratePhysicalDevices(instance, &n, handles.data());
    std::vector<DeviceSummary> out;
    for (VkPhysicalDevice pd : handles) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(pd, &props);
        out.push_back({pd, props.deviceName, props.apiVersion, props.deviceType});
    }
    return out;
}

std::string describe(const DeviceSummary& d) {
    return d.name + " (Vulkan " + std::to_string(VK_API_VERSION_MAJOR(d.api_version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(d.api_version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(d.api_version)) + ")";
}

void Context::pick_physical_device(const ContextOptions& options) {
    const std::vector<DeviceSummary> devices = enumerate_devices(instance_);
    if (devices.empty()) throw GpuError("no Vulkan device found");

    const std::string filter =
        options.device_filter.empty() ? env_or("SHERPA_DEVICE", "") : options.device_filter;
    std::string rejected;
    VkPhysicalDevice best = VK_NULL_HANDLE;
    int best_score = -1;
    for (const DeviceSummary& d : devices) {
        const VkPhysicalDevice pd = d.handle;
        const std::string& name = d.name;
        if (!filter.empty() && name.find(filter) == std::string::npos) continue;
        if (d.api_version < VK_API_VERSION_1_3) {
            rejected += name + ": Vulkan < 1.3; ";
            continue;
        }
        FeatureChain f;
        vkGetPhysicalDeviceFeatures2(pd, &f.core);
        if (auto missing = missing_features(f); !missing.empty()) {
            rejected += name + ": lacks " + missing + "; ";
            continue;
        }
        // Subgroup vote (forward shading's sun branch) in fragment shaders, vote and
        // ballot (GPU culling's one atomic per subgroup) in compute shaders.
        auto subgroup = vk_init<VkPhysicalDeviceSubgroupProperties>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES);
        auto props2 =
            vk_init<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
        props2.pNext = &subgroup;
        vkGetPhysicalDeviceProperties2(pd, &props2);
        const VkSubgroupFeatureFlags ops =
            VK_SUBGROUP_FEATURE_VOTE_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
        if ((subgroup.supportedOperations & ops) != ops ||
            (subgroup.supportedStages & VK_SHADER_STAGE_FRAGMENT_BIT) == 0 ||
            (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) == 0) {
            rejected += name + ": lacks subgroup vote/ballot in fragment and compute shaders; ";
            continue;
        }
        // Lavapipe is the default everywhere (reproducible images); otherwise any.
        const int score = name.find("llvmpipe") != std::string::npos ? 2 : 1;
        if (score > best_score) {
            best = pd;
            best_score = score;
        }
    }
    if (!best)
        throw GpuError("no suitable Vulkan device" +
                       (filter.empty() ? "" : " matching '" + filter + "'") +
                       (rejected.empty() ? std::string() : ": " + rejected));
    physical_ = best;

    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical_, &props);
    info_.name = props.deviceName;
    info_.api_version = props.apiVersion;
    info_.driver_version = props.driverVersion;
    info_.type = props.deviceType;
    info_.timestamp_period_ns = props.limits.timestampPeriod;
    info_.max_anisotropy = props.limits.maxSamplerAnisotropy;
    vkGetPhysicalDeviceMemoryProperties(physical_, &info_.memory);
}

} // namespace sherpa::gpu
