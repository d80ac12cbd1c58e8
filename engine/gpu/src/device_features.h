#pragma once
// Device feature checks shared by device selection (devices.cpp) and device
// creation (context.cpp). Private to the RHI.
#include <sherpa/gpu/gpu_error.h>

#include <string>

namespace sherpa::gpu {

// The Vulkan 1.0-1.3 feature structures, chained.
struct FeatureChain {
    VkPhysicalDeviceFeatures2 core =
        vk_init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    VkPhysicalDeviceVulkan11Features v11 = vk_init<VkPhysicalDeviceVulkan11Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    VkPhysicalDeviceVulkan12Features v12 = vk_init<VkPhysicalDeviceVulkan12Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    VkPhysicalDeviceVulkan13Features v13 = vk_init<VkPhysicalDeviceVulkan13Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    FeatureChain() {
        core.pNext = &v11;
        v11.pNext = &v12;
        v12.pNext = &v13;
    }
    FeatureChain(const FeatureChain&) = delete;
};

// The features the renderer cannot work without that `f` lacks, comma separated.
inline std::string missing_features(const FeatureChain& f) {
    std::string missing;
    auto need = [&](VkBool32 v, const char* name) {
        if (!v) missing += std::string(missing.empty() ? "" : ", ") + name;
    };
    need(f.core.features.shaderInt64, "shaderInt64");
    need(f.core.features.fillModeNonSolid, "fillModeNonSolid");
    need(f.core.features.multiDrawIndirect, "multiDrawIndirect");
    need(f.v12.drawIndirectCount, "drawIndirectCount");
    need(f.v12.descriptorIndexing, "descriptorIndexing");
    need(f.v12.runtimeDescriptorArray, "runtimeDescriptorArray");
    need(f.v12.descriptorBindingPartiallyBound, "descriptorBindingPartiallyBound");
    need(f.v12.descriptorBindingVariableDescriptorCount,
         "descriptorBindingVariableDescriptorCount");
    need(f.v12.descriptorBindingSampledImageUpdateAfterBind,
         "descriptorBindingSampledImageUpdateAfterBind");
    need(f.v12.shaderSampledImageArrayNonUniformIndexing,
         "shaderSampledImageArrayNonUniformIndexing");
    need(f.v12.descriptorBindingUpdateUnusedWhilePending,
         "descriptorBindingUpdateUnusedWhilePending");
    need(f.v12.bufferDeviceAddress, "bufferDeviceAddress");
    need(f.v12.scalarBlockLayout, "scalarBlockLayout");
    need(f.v12.hostQueryReset, "hostQueryReset");
    need(f.v13.dynamicRendering, "dynamicRendering");
    need(f.v13.synchronization2, "synchronization2");
    return missing;
}

} // namespace sherpa::gpu
