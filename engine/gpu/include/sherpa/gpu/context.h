#pragma once
// The Vulkan instance, physical device and logical device the engine renders with.
// Requires Vulkan 1.3 with dynamic rendering, synchronization2, descriptor
// indexing, buffer device address and scalar block layout. Acceleration structures
// and ray-tracing pipelines (and ray query) are enabled where the device has them,
// unless ContextOptions::ray_tracing is off. No window-system types: a caller that wants
// to present creates its surface from instance() (or hands in its own instance
// created with required_instance_extensions()).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <sherpa/gpu/unique_handle.h>
#include <sherpa/gpu/validation.h>

namespace sherpa::gpu {

struct ContextOptions {
    // Khronos validation layer and a debug messenger recording into validation().
    // Default: on in debug builds; SHERPA_VALIDATION=0/1 in the environment overrides.
    bool validation = default_validation();
    // Extra instance extensions (e.g. VK_KHR_xcb_surface for a window).
    std::vector<std::string> instance_extensions;
    // Substring of the device name to pick; empty: SHERPA_DEVICE from the environment,
    // else lavapipe (llvmpipe) when present, else the first device with the features.
    std::string device_filter;
    // Adopt an instance created by the caller (with required_instance_extensions()).
    // It stays owned by the caller and must outlive the Context.
    VkInstance external_instance = VK_NULL_HANDLE;

    // Enable VK_KHR_surface on the instance and VK_KHR_swapchain on the device. Add
    // the platform's surface extension (e.g. VK_KHR_xcb_surface) to instance_extensions.
    bool presentation = false;
    // Print each validation message to stderr as it arrives (from instance creation on).
    bool echo_validation = false;
    // Enable acceleration structures and ray-tracing pipelines (+ ray query) where the
    // device has them. Off (`--rt off`): none of it is enabled, and nothing the engine
    // allocates carries acceleration-structure or extra device-address usage.
    bool ray_tracing = true;

    static bool default_validation();
};

struct DeviceInfo {
    std::string name;
    std::uint32_t api_version = 0;
    std::uint32_t driver_version = 0;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    // What the device supports: acceleration structures + ray-tracing pipelines, and
    // ray query (with acceleration structures).
    bool ray_tracing = false;
    bool ray_query = false;
    // What this context enabled (support and ContextOptions::ray_tracing).
    bool ray_tracing_enabled = false;
    bool ray_query_enabled = false;
    // VkPhysicalDeviceAccelerationStructurePropertiesKHR / RayTracingPipelineProperties
    // (0 while ray tracing is not enabled).
    std::uint32_t as_scratch_alignment = 0;
    std::uint32_t shader_group_handle_size = 0, shader_group_handle_alignment = 0,
                  shader_group_base_alignment = 0;
    bool swapchain = false; // VK_KHR_swapchain enabled
    bool anisotropy = false;
    bool wide_lines = false;
    bool large_points = false; // point sizes above 1 px (largePoints)
    float timestamp_period_ns = 1.0f;
    bool timestamps = false;
    bool pipeline_statistics = false;
    float max_anisotropy = 1.0f;
    // BC7 (sRGB and UNORM) and BC5 can be sampled with linear filtering from
    // optimally tiled images (textureCompressionBC enabled and the format
    // properties say so); false: textures fall back to RGBA8.
    bool bc_textures = false;
    // Memory heaps and types; the RHI's allocator picks from them.
    VkPhysicalDeviceMemoryProperties memory{};
    bool is_cpu() const { return type == VK_PHYSICAL_DEVICE_TYPE_CPU; }
};

class Context {
public:
    explicit Context(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Instance extensions the engine needs when the caller creates the instance
    // (VK_KHR_surface is added when presenting; debug utils when validating).
    static std::vector<std::string> required_instance_extensions(bool validation,
                                                                 bool presentation);

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queue_family() const { return queue_family_; }
    const DeviceInfo& info() const { return info_; }
    const ValidationLog& validation() const { return *validation_; }
    ValidationLog& validation() { return *validation_; }

    void set_debug_name(VkObjectType type, std::uint64_t handle, const char* name) const;
    void wait_idle() const;

private:
    void create_instance(const ContextOptions& options);
    void pick_physical_device(const ContextOptions& options);
    void create_device(bool presentation, bool ray_tracing);
    void destroy();

    std::unique_ptr<ValidationLog> validation_;
    VkInstance instance_ = VK_NULL_HANDLE;
    bool owns_instance_ = false;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queue_family_ = 0;
    DeviceInfo info_;
    PFN_vkSetDebugUtilsObjectNameEXT set_name_ = nullptr;
};

} // namespace sherpa::gpu
