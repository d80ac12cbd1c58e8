#include <sherpa/gpu/acceleration_structure.h>

#include <sherpa/gpu/gpu_error.h>

#include <utility>

namespace sherpa::gpu {

namespace {

template <typename Fn> void load_one(VkDevice device, Fn& out, const char* name) {
    out = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
    if (!out) throw GpuError(std::string("ray tracing: the device has no ") + name);
}

} // namespace

RayTracingFunctions RayTracingFunctions::load(const Context& context) {
    if (!context.info().ray_tracing_enabled)
        throw GpuError(context.info().name + ": ray tracing is not enabled on this device" +
                       (context.info().ray_tracing ? " (switched off)" : " (not supported)"));
    const VkDevice d = context.device();
    RayTracingFunctions f;
    load_one(d, f.create_acceleration_structure, "vkCreateAccelerationStructureKHR");
    load_one(d, f.get_build_sizes, "vkGetAccelerationStructureBuildSizesKHR");
    load_one(d, f.get_device_address, "vkGetAccelerationStructureDeviceAddressKHR");
    load_one(d, f.cmd_build, "vkCmdBuildAccelerationStructuresKHR");
    load_one(d, f.cmd_copy, "vkCmdCopyAccelerationStructureKHR");
    load_one(d, f.cmd_write_properties, "vkCmdWriteAccelerationStructuresPropertiesKHR");
    load_one(d, f.create_pipelines, "vkCreateRayTracingPipelinesKHR");
    load_one(d, f.get_group_handles, "vkGetRayTracingShaderGroupHandlesKHR");
    load_one(d, f.cmd_trace_rays, "vkCmdTraceRaysKHR");
    return f;
}

void destroy_acceleration_structure(VkDevice device, VkAccelerationStructureKHR handle,
                                    const VkAllocationCallbacks* allocator) {
    auto destroy = reinterpret_cast<PFN_vkDestroyAccelerationStructureKHR>(
        vkGetDeviceProcAddr(device, "vkDestroyAccelerationStructureKHR"));
    if (destroy) destroy(device, handle, allocator);
}

AccelerationStructure::AccelerationStructure(ResourceManager& resources,
                                             const RayTracingFunctions& fn,
                                             VkAccelerationStructureTypeKHR type, VkDeviceSize size,
                                             const std::string& name)
    : resources_(&resources), size_(size) {
    buffer_ = resources.create_buffer({size,
                                       VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                           VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                       MemoryUsage::DeviceLocal, name});
    const VkDevice device = resources.context().device();
    auto ci = vk_init<VkAccelerationStructureCreateInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR);
    ci.buffer = resources.get(buffer_).buffer.get();
    ci.size = size;
    ci.type = type;
    VkAccelerationStructureKHR raw = VK_NULL_HANDLE;
    const VkResult r = fn.create_acceleration_structure(device, &ci, nullptr, &raw);
    if (r != VK_SUCCESS) {
        resources.destroy(buffer_);
        vk_check(r, "vkCreateAccelerationStructureKHR");
    }
    handle_ = UniqueAccelerationStructure(device, raw);
    auto ai = vk_init<VkAccelerationStructureDeviceAddressInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR);
    ai.accelerationStructure = raw;
    address_ = fn.get_device_address(device, &ai);
    resources.context().set_debug_name(VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR,
                                       reinterpret_cast<std::uint64_t>(raw), name.c_str());
}

AccelerationStructure::~AccelerationStructure() {
    reset();
}

void AccelerationStructure::reset() {
    handle_.reset();
    if (resources_) resources_->destroy(buffer_);
    address_ = 0;
    size_ = 0;
}

AccelerationStructure::AccelerationStructure(AccelerationStructure&& o) noexcept
    : resources_(o.resources_), buffer_(std::exchange(o.buffer_, {})),
      handle_(std::move(o.handle_)), address_(std::exchange(o.address_, 0)),
      size_(std::exchange(o.size_, 0)) {}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& o) noexcept {
    if (this != &o) {
        reset();
        resources_ = o.resources_;
        buffer_ = std::exchange(o.buffer_, {});
        handle_ = std::move(o.handle_);
        address_ = std::exchange(o.address_, 0);
        size_ = std::exchange(o.size_, 0);
    }
    return *this;
}

} // namespace sherpa::gpu
