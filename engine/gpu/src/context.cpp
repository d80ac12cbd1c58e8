#include "device_features.h"
#include "ray_tracing_features.h"
#include <sherpa/gpu/context.h>

#include <sherpa/gpu/gpu_error.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace sherpa::gpu {

bool has_extension(const std::vector<VkExtensionProperties>& list, const char* name) {
    return std::any_of(list.begin(), list.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::vector<VkExtensionProperties> device_extensions(VkPhysicalDevice pd) {
    std::uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> out(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, out.data());
    return out;
}

} // namespace

bool ContextOptions::default_validation() {
    if (const char* v = std::getenv("SHERPA_VALIDATION"); v && *v)
        return std::string_view(v) != "0";
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

std::vector<std::string> Context::required_instance_extensions(bool validation, bool presentation) {
    std::vector<std::string> out;
    if (validation) out.emplace_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (presentation) out.emplace_back(VK_KHR_SURFACE_EXTENSION_NAME);
    return out;
}

Context::Context(const ContextOptions& options)
    : validation_(std::make_unique<ValidationLog>(options.validation)) {
    validation_->set_echo(options.echo_validation);
    try {
        create_instance(options);
        pick_physical_device(options);
        create_device(options.presentation, options.ray_tracing);
    } catch (...) {
        destroy(); // the destructor does not run for a throwing constructor
        throw;
    }
}

Context::~Context() {
    destroy();
}

void Context::destroy() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_ && owns_instance_) vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
}

void Context::create_instance(const ContextOptions& options) {
    std::uint32_t loader_version = VK_API_VERSION_1_0;
    vkEnumerateInstanceVersion(&loader_version);
    if (loader_version < VK_API_VERSION_1_3)
        throw GpuError("the Vulkan loader supports only " +
                       std::to_string(VK_API_VERSION_MAJOR(loader_version)) + "." +
                       std::to_string(VK_API_VERSION_MINOR(loader_version)) + ", need 1.3");

    bool validation = options.validation;
    std::uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    const bool have_layer =
        std::any_of(layers.begin(), layers.end(), [](const VkLayerProperties& l) {
            return std::strcmp(l.layerName, kValidationLayer) == 0;
        });
    if (validation && !have_layer)
        throw GpuError("validation requested but VK_LAYER_KHRONOS_validation is not installed");

    VkDebugUtilsMessengerCreateInfoEXT messenger_info = vk_init<VkDebugUtilsMessengerCreateInfoEXT>(
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                     VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = &ValidationLog::callback;
    messenger_info.pUserData = validation_.get();

    if (options.external_instance) {
        instance_ = options.external_instance;
        owns_instance_ = false;
    } else {
        std::vector<std::string> ext_names = options.instance_extensions;
        for (auto& e : required_instance_extensions(validation, options.presentation))
            ext_names.push_back(e);
        std::sort(ext_names.begin(), ext_names.end());
        ext_names.erase(std::unique(ext_names.begin(), ext_names.end()), ext_names.end());
        std::vector<const char*> exts;
        for (auto& e : ext_names) exts.push_back(e.c_str());

        VkApplicationInfo app = vk_init<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
        app.pApplicationName = "Sherpa";
        app.pEngineName = "Sherpa";
        app.apiVersion = VK_API_VERSION_1_3;
        VkInstanceCreateInfo ci =
            vk_init<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
        ci.pApplicationInfo = &app;
        ci.enabledExtensionCount = static_cast<std::uint32_t>(exts.size());
        ci.ppEnabledExtensionNames = exts.data();
        if (validation) {
            ci.enabledLayerCount = 1;
            ci.ppEnabledLayerNames = &kValidationLayer;
            ci.pNext = &messenger_info; // also catches messages of instance creation itself
        }
        vk_check(vkCreateInstance(&ci, nullptr, &instance_), "vkCreateInstance");
        owns_instance_ = true;
    }
    if (validation) {
        auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create_messenger)
            throw GpuError("validation requested but the instance lacks VK_EXT_debug_utils");
        vk_check(create_messenger(instance_, &messenger_info, nullptr, &messenger_),
                 "vkCreateDebugUtilsMessengerEXT");
        set_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
    }
}

namespace {

// The block-compressed formats the texture pipeline writes, each sampled with
// linear filtering from an optimally tiled image.
bool samples_bc(VkPhysicalDevice physical) {
    constexpr VkFormatFeatureFlags kNeeded = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                             VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                             VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    for (VkFormat format :
         {VK_FORMAT_BC7_SRGB_BLOCK, VK_FORMAT_BC7_UNORM_BLOCK, VK_FORMAT_BC5_UNORM_BLOCK}) {
        VkFormatProperties props;
        vkGetPhysicalDeviceFormatProperties(physical, format, &props);
        if ((props.optimalTilingFeatures & kNeeded) != kNeeded) return false;
    }
    return true;
}

} // namespace

void Context::create_device(bool presentation, bool ray_tracing) {
    std::uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, families.data());
    bool found = false;
    for (std::uint32_t i = 0; i < n; ++i) {
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
            queue_family_ = i;
            info_.timestamps = families[i].timestampValidBits > 0;
            found = true;
            break;
        }
    }
    if (!found) throw GpuError(info_.name + ": no graphics queue");

    FeatureChain supported;
    vkGetPhysicalDeviceFeatures2(physical_, &supported.core);
    const auto exts = device_extensions(physical_);

    // Enable exactly what the renderer uses; optional features only where present.
    FeatureChain f;
    f.core.features.shaderInt64 = VK_TRUE;
    f.core.features.fillModeNonSolid = VK_TRUE;
    f.core.features.multiDrawIndirect = VK_TRUE; // GPU-driven culling's indirect draws
    f.core.features.samplerAnisotropy = supported.core.features.samplerAnisotropy;
    f.core.features.wideLines = supported.core.features.wideLines;
    f.core.features.largePoints = supported.core.features.largePoints; // points drawn > 1 px
    f.core.features.pipelineStatisticsQuery = supported.core.features.pipelineStatisticsQuery;
    f.core.features.depthClamp = supported.core.features.depthClamp;
    f.core.features.textureCompressionBC = supported.core.features.textureCompressionBC;
    f.v11.shaderDrawParameters = supported.v11.shaderDrawParameters;
    f.v12.descriptorIndexing = VK_TRUE;
    f.v12.runtimeDescriptorArray = VK_TRUE;
    f.v12.descriptorBindingPartiallyBound = VK_TRUE;
    f.v12.descriptorBindingVariableDescriptorCount = VK_TRUE;
    f.v12.descriptorBindingSampledImageUpdateAfterBind = VK_TRUE;
    f.v12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    f.v12.descriptorBindingUpdateUnusedWhilePending = VK_TRUE;
    f.v12.bufferDeviceAddress = VK_TRUE;
    f.v12.scalarBlockLayout = VK_TRUE;
    f.v12.hostQueryReset = VK_TRUE;
    f.v12.drawIndirectCount = VK_TRUE;
    f.v12.timelineSemaphore = supported.v12.timelineSemaphore;
    f.v13.dynamicRendering = VK_TRUE;
    f.v13.synchronization2 = VK_TRUE;
    f.v13.maintenance4 = supported.v13.maintenance4;
    info_.anisotropy = f.core.features.samplerAnisotropy;
    info_.wide_lines = f.core.features.wideLines;
    info_.large_points = f.core.features.largePoints;
    info_.pipeline_statistics = f.core.features.pipelineStatisticsQuery;
    info_.bc_textures = f.core.features.textureCompressionBC && samples_bc(physical_);

    std::vector<const char*> enabled;
    // Ray tracing: recorded always, enabled where supported unless switched off.
    RayTracingFeatures rt;
    rt.query_support(physical_, exts);
    info_.ray_tracing = rt.pipelines;
    info_.ray_query = rt.query;
    if (ray_tracing && rt.pipelines) {
        rt.enable(f.v13, enabled);
        info_.ray_tracing_enabled = true;
        info_.ray_query_enabled = rt.query;
        record_ray_tracing_properties(physical_, info_);
    }

    if (presentation) {
        if (!has_extension(exts, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
            throw GpuError(info_.name + ": presentation requested but VK_KHR_swapchain is missing");
        enabled.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        info_.swapchain = true;
    }

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci =
        vk_init<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    qci.queueFamilyIndex = queue_family_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo ci = vk_init<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    ci.pNext = &f.core;
    ci.queueCreateInfoCount = 1;
    ci.pQueueCreateInfos = &qci;
    ci.enabledExtensionCount = static_cast<std::uint32_t>(enabled.size());
    ci.ppEnabledExtensionNames = enabled.data();
    vk_check(vkCreateDevice(physical_, &ci, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
}

void Context::set_debug_name(VkObjectType type, std::uint64_t handle, const char* name) const {
    if (!set_name_ || !name) return;
    VkDebugUtilsObjectNameInfoEXT ni =
        vk_init<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
    ni.objectType = type;
    ni.objectHandle = handle;
    ni.pObjectName = name;
    set_name_(device_, &ni);
}

void Context::wait_idle() const {
    vk_check(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle");
}

std::string to_string(VkResult r) {
    switch (r) {
    case VK_SUCCESS:
        return "VK_SUCCESS";
    case VK_NOT_READY:
        return "VK_NOT_READY";
    case VK_TIMEOUT:
        return "VK_TIMEOUT";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
        return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
        return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED:
        return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST:
        return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT:
        return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT:
        return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT:
        return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
        return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_SURFACE_LOST_KHR:
        return "VK_ERROR_SURFACE_LOST_KHR";
    case VK_ERROR_OUT_OF_DATE_KHR:
        return "VK_ERROR_OUT_OF_DATE_KHR";
    case VK_SUBOPTIMAL_KHR:
        return "VK_SUBOPTIMAL_KHR";
    default:
        return "VkResult(" + std::to_string(static_cast<int>(r)) + ")";
    }
}

void vk_check(VkResult r, const char* what) {
    if (r != VK_SUCCESS) throw GpuError(std::string(what) + " failed: " + to_string(r));
}

std::int64_t live_vulkan_objects() {
    return detail::g_live_objects.load();
}
namespace detail {
std::atomic<std::int64_t> g_live_objects{0};
}

} // namespace sherpa::gpu
