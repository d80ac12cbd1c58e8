#include "ray_tracing_features.h"

#include <algorithm>
#include <cstring>

namespace sherpa::gpu {

void RayTracingFeatures::query_support(VkPhysicalDevice physical,
                                       const std::vector<VkExtensionProperties>& extensions) {
    pipelines = query = false;
    if (!has_extension(extensions, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) ||
        !has_extension(extensions, VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME))
        return;
    as_.pNext = &pipeline_;
    pipeline_.pNext = &query_;
    VkPhysicalDeviceFeatures2 f2 =
        vk_init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    f2.pNext = &as_;
    vkGetPhysicalDeviceFeatures2(physical, &f2);
    pipelines = as_.accelerationStructure && pipeline_.rayTracingPipeline &&
                has_extension(extensions, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
    query = as_.accelerationStructure && query_.rayQuery &&
            has_extension(extensions, VK_KHR_RAY_QUERY_EXTENSION_NAME);
}

void RayTracingFeatures::enable(VkPhysicalDeviceVulkan13Features& last,
                                std::vector<const char*>& extensions) {
    // Exactly what the engine uses, not everything the query reported.
    as_ = vk_init<VkPhysicalDeviceAccelerationStructureFeaturesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR);
    pipeline_ = vk_init<VkPhysicalDeviceRayTracingPipelineFeaturesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR);
    query_ = vk_init<VkPhysicalDeviceRayQueryFeaturesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR);
    as_.accelerationStructure = VK_TRUE;
    pipeline_.rayTracingPipeline = VK_TRUE;
    as_.pNext = &pipeline_;
    extensions.push_back(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
    extensions.push_back(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
    extensions.push_back(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
    if (query) {
        query_.rayQuery = VK_TRUE;
        pipeline_.pNext = &query_;
        extensions.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
    }
    last.pNext = &as_;
}

void record_ray_tracing_properties(VkPhysicalDevice physical, DeviceInfo& info) {
    auto as = vk_init<VkPhysicalDeviceAccelerationStructurePropertiesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR);
    auto rt = vk_init<VkPhysicalDeviceRayTracingPipelinePropertiesKHR>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR);
    as.pNext = &rt;
    auto props2 =
        vk_init<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    props2.pNext = &as;
    vkGetPhysicalDeviceProperties2(physical, &props2);
    info.as_scratch_alignment = std::max(1u, as.minAccelerationStructureScratchOffsetAlignment);
    info.shader_group_handle_size = rt.shaderGroupHandleSize;
    info.shader_group_handle_alignment = rt.shaderGroupHandleAlignment;
    info.shader_group_base_alignment = rt.shaderGroupBaseAlignment;
}

} // namespace sherpa::gpu
