#pragma once
// Ray-tracing support of a physical device and what enabling it takes: the
// acceleration-structure, ray-tracing-pipeline and ray-query feature structures
// chained into device creation, and their extensions. Private to the RHI (context.cpp).
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/gpu_error.h>

#include <vector>

namespace sherpa::gpu {

// Whether `list` (vkEnumerateDeviceExtensionProperties) names extension `name`
// (context.cpp).
bool has_extension(const std::vector<VkExtensionProperties>& list, const char* name);

struct RayTracingFeatures {
    bool pipelines = false; // acceleration structures + ray-tracing pipelines
    bool query = false;     // acceleration structures + ray query

    // Fills `pipelines` and `query` with what `physical` supports.
    void query_support(VkPhysicalDevice physical,
                       const std::vector<VkExtensionProperties>& extensions);
    // Chains the enabled features behind `last` (whose pNext must be null) and adds
    // the extensions; the structures live in this object, which must outlive
    // vkCreateDevice.
    void enable(VkPhysicalDeviceVulkan13Features& last, std::vector<const char*>& extensions);

    RayTracingFeatures() = default;
    RayTracingFeatures(const RayTracingFeatures&) = delete;
    RayTracingFeatures(RayTracingFeatures&&) = delete;

private:
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as_ =
        vk_init<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR);
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline_ =
        vk_init<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR);
    VkPhysicalDeviceRayQueryFeaturesKHR query_ = vk_init<VkPhysicalDeviceRayQueryFeaturesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR);
};

// Scratch alignment and shader-group sizes, into `info`.
void record_ray_tracing_properties(VkPhysicalDevice physical, DeviceInfo& info);

} // namespace sherpa::gpu
