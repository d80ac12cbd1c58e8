#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/presenter.h>

#include <algorithm>

namespace sherpa::gpu {

namespace {

UniqueSemaphore make_semaphore(VkDevice device) {
    auto ci = vk_init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    VkSemaphore s = VK_NULL_HANDLE;
    vk_check(vkCreateSemaphore(device, &ci, nullptr, &s), "vkCreateSemaphore");
    return UniqueSemaphore(device, s);
}

// sRGB formats let the hardware encode our linear output; others would show it
// too dark, so they are a last resort.
VkSurfaceFormatKHR pick_format(const std::vector<VkSurfaceFormatKHR>& formats) {
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
        for (const auto& f : formats)
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    return formats.front();
}

} // namespace

Presenter::Presenter(Context& context, ResourceManager& resources, VkSurfaceKHR surface,
                     std::uint32_t width, std::uint32_t height, const PresenterOptions& options)
    : context_(context), resources_(resources), surface_(surface), options_(options) {
    if (!context_.info().swapchain)
        throw GpuError(
            "the Context was created without presentation (ContextOptions::presentation)");
    VkBool32 supported = VK_FALSE;
    vk_check(vkGetPhysicalDeviceSurfaceSupportKHR(context_.physical_device(),
                                                  context_.queue_family(), surface_, &supported),
             "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported)
        throw GpuError(context_.info().name +
                       " cannot present to this surface from its graphics queue");
    create_swapchain(width, height);
}

Presenter::~Presenter() {
    // Presentation may still read the images; nothing of ours may go before it ends.
    vkQueueWaitIdle(context_.queue());
    resources_.collect_garbage();
}

// One acquire semaphore and one command recorder per frame slot of the source.
void Presenter::make_slots(std::uint32_t frames_in_flight) {
    if (!acquired_.empty()) {
        if (acquired_.size() != frames_in_flight)
            throw GpuError("a frame source with " + std::to_string(frames_in_flight) +
                           " frames in flight given to a presenter made for " +
                           std::to_string(acquired_.size()));
        return;
    }
    if (frames_in_flight == 0) throw GpuError("a frame source with no frames in flight");
    for (std::uint32_t i = 0; i < frames_in_flight; ++i) {
        acquired_.push_back(make_semaphore(context_.device()));
        recorders_.push_back(std::make_unique<CommandRecorder>(context_));
    }
}

void Presenter::destroy_swapchain_views() {
    views_.clear();
    rendered_.clear();
}

void Presenter::create_swapchain(std::uint32_t width, std::uint32_t height) {
    VkPhysicalDevice pd = context_.physical_device();
    VkSurfaceCapabilitiesKHR caps;
    vk_check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(pd, surface_, &caps),
             "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    std::uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface_, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface_, &n, formats.data());
    if (formats.empty()) throw GpuError("the surface offers no formats");
    vkGetPhysicalDeviceSurfacePresentModesKHR(pd, surface_, &n, nullptr);
    std::vector<VkPresentModeKHR> modes(n);
    vkGetPhysicalDeviceSurfacePresentModesKHR(pd, surface_, &n, modes.data());

    const VkSurfaceFormatKHR format = pick_format(formats);
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR; // the only mode every device has
    if (!options_.vsync)
        for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
            if (std::find(modes.begin(), modes.end(), want) != modes.end()) {
                mode = want;
                break;
            }
    // The window system decides the size unless it reports the special 0xFFFFFFFF.
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == 0xFFFFFFFFu) {
        extent.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    std::uint32_t count = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);

    auto ci = vk_init<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
    ci.surface = surface_;
    ci.minImageCount = count;
    ci.imageFormat = format.format;
    ci.imageColorSpace = format.colorSpace;
    ci.imageExtent = extent;
    ci.imageArrayLayers = 1;
    // Transfer writes too where allowed: reduced-resolution frames are blitted in.
    blit_target_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT) != 0;
    ci.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if (blit_target_) ci.imageUsage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = caps.currentTransform;
    ci.compositeAlpha =
        (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
            : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                       (~caps.supportedCompositeAlpha + 1));
    ci.presentMode = mode;
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = swapchain_.get();
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    vk_check(vkCreateSwapchainKHR(context_.device(), &ci, nullptr, &swapchain),
             "vkCreateSwapchainKHR");
    destroy_swapchain_views();
    swapchain_ = UniqueSwapchain(context_.device(), swapchain); // retires the old one
    format_ = format.format;
    extent_ = extent;
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(pd, format_, &props);
    const VkFormatFeatureFlags blit =
        VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
    blit_target_ = blit_target_ && (props.optimalTilingFeatures & blit) == blit;
    blit_filter_ = (props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
                       ? VK_FILTER_LINEAR
                       : VK_FILTER_NEAREST;

    vkGetSwapchainImagesKHR(context_.device(), swapchain, &n, nullptr);
    images_.resize(n);
    vkGetSwapchainImagesKHR(context_.device(), swapchain, &n, images_.data());
    for (VkImage image : images_) {
        auto vi = vk_init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format_;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        vk_check(vkCreateImageView(context_.device(), &vi, nullptr, &view),
                 "vkCreateImageView(swapchain)");
        views_.emplace_back(context_.device(), view);
        rendered_.push_back(make_semaphore(context_.device()));
    }
}

void Presenter::resize(std::uint32_t width, std::uint32_t height) {
    // Old images may still be in use by frames or by presentation.
    vkQueueWaitIdle(context_.queue());
    create_swapchain(width, height);
}

bool Presenter::present_frame(FrameSource& source) {
    if (extent_.width == 0 || extent_.height == 0) return false; // minimised
    make_slots(source.frames_in_flight());
    const std::uint32_t slot = frame_;
    source.wait_for_slot(slot); // its acquire semaphore and recorder are free again
    std::uint32_t index = 0;
    VkResult r = vkAcquireNextImageKHR(context_.device(), swapchain_.get(), UINT64_MAX,
                                       acquired_[slot].get(), VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        resize(extent_.width, extent_.height);
        return false;
    }
    if (r != VK_SUBOPTIMAL_KHR) vk_check(r, "vkAcquireNextImageKHR");

    VkCommandBuffer cmd = recorders_[slot]->begin();
    const RenderTarget target{images_[index], views_[index].get(), format_,
                              extent_.width,  extent_.height,      VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                              blit_target_,   blit_filter_};
    source.record(cmd, slot, target);
    auto wait = vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    wait.semaphore = acquired_[slot].get();
    // Where the image is first written: drawn into, or a reduced frame blitted in.
    wait.stageMask =
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    std::vector<VkSemaphoreSubmitInfo> signals{
        vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO)};
    signals[0].semaphore = rendered_[index].get();
    signals[0].stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    for (const VkSemaphoreSubmitInfo& s : source.signals(slot)) signals.push_back(s);
    const std::uint64_t value = recorders_[slot]->submit(
        resources_, &wait, 1, signals.data(), static_cast<std::uint32_t>(signals.size()));
    source.submitted(slot, value);
    frame_ = (frame_ + 1) % static_cast<std::uint32_t>(acquired_.size());

    VkSemaphore rendered = rendered_[index].get();
    VkSwapchainKHR swapchain = swapchain_.get();
    auto pi = vk_init<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &rendered;
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain;
    pi.pImageIndices = &index;
    r = vkQueuePresentKHR(context_.queue(), &pi);
    resources_.collect_garbage();
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        resize(extent_.width, extent_.height);
        return r == VK_SUBOPTIMAL_KHR; // a suboptimal frame was still shown
    }
    vk_check(r, "vkQueuePresentKHR");
    ++presented_;
    return true;
}

} // namespace sherpa::gpu
