#pragma once
// Acceleration structures in the RHI: the extension entry points (the loader
// exports only core functions), RAII for VkAccelerationStructureKHR, and one
// acceleration structure with the buffer that stores it. Only usable on a Context
// with DeviceInfo::ray_tracing_enabled.
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/gpu/unique_handle.h>

namespace sherpa::gpu {

// The ray-tracing entry points of one device.
struct RayTracingFunctions {
    PFN_vkCreateAccelerationStructureKHR create_acceleration_structure = nullptr;
    PFN_vkGetAccelerationStructureBuildSizesKHR get_build_sizes = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR get_device_address = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR cmd_build = nullptr;
    PFN_vkCmdCopyAccelerationStructureKHR cmd_copy = nullptr;
    PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmd_write_properties = nullptr;
    PFN_vkCreateRayTracingPipelinesKHR create_pipelines = nullptr;
    PFN_vkGetRayTracingShaderGroupHandlesKHR get_group_handles = nullptr;
    PFN_vkCmdTraceRaysKHR cmd_trace_rays = nullptr;

    // Throws GpuError when the context did not enable ray tracing.
    static RayTracingFunctions load(const Context& context);
};

// vkDestroyAccelerationStructureKHR, looked up for `device` (a DeviceHandle destroyer).
void destroy_acceleration_structure(VkDevice device, VkAccelerationStructureKHR handle,
                                    const VkAllocationCallbacks* allocator);
using UniqueAccelerationStructure =
    DeviceHandle<VkAccelerationStructureKHR, destroy_acceleration_structure>;

// One acceleration structure and its storage buffer. The owner destroys it only
// once the GPU no longer uses it (the structure goes at once, the buffer through
// the ResourceManager's deferred release).
class AccelerationStructure {
public:
    AccelerationStructure() = default;
    AccelerationStructure(ResourceManager& resources, const RayTracingFunctions& fn,
                          VkAccelerationStructureTypeKHR type, VkDeviceSize size,
                          const std::string& name);
    ~AccelerationStructure();
    AccelerationStructure(AccelerationStructure&& o) noexcept;
    AccelerationStructure& operator=(AccelerationStructure&& o) noexcept;

    VkAccelerationStructureKHR get() const { return handle_.get(); }
    VkDeviceAddress address() const { return address_; }
    VkDeviceSize size() const { return size_; } // bytes of its storage buffer
    explicit operator bool() const { return bool(handle_); }

private:
    void reset();

    ResourceManager* resources_ = nullptr;
    BufferHandle buffer_;
    UniqueAccelerationStructure handle_;
    VkDeviceAddress address_ = 0;
    VkDeviceSize size_ = 0;
};

} // namespace sherpa::gpu
