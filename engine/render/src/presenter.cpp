#include "renderer_impl.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/presenter.h>

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

Presenter::Presenter(Renderer& renderer, VkSurfaceKHR surface, std::uint32_t width,
                     std::uint32_t height, const PresenterOptions& options)
    : renderer_(renderer), context_(renderer.context()), surface_(surface), options_(options) {
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
    for (std::uint32_t i = 0; i < Renderer::kFramesInFlight; ++i) {
        acquired_.push_back(make_semaphore(context_.device()));
        recorders_.push_back(std::make_unique<CommandRecorder>(context_));
    }
    create_swapchain(width, height);
}

Presenter::~Presenter() {
    // Presentation may still read the images; nothing of ours may go before it ends.
    vkQueueWaitIdle(context_.queue());
    renderer_.resources().collect_garbage();
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

namespace {

// The reduced frame (in TRANSFER_SRC layout) stretched over the whole swapchain image.
void blit_to_swapchain(VkCommandBuffer cmd, VkImage from, VkExtent2D from_size, VkImage to,
                       VkExtent2D to_size, VkFilter filter) {
    transition(cmd, {to, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_NONE, // the acquire wait
                     VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {static_cast<std::int32_t>(from_size.width),
                            static_cast<std::int32_t>(from_size.height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {static_cast<std::int32_t>(to_size.width),
                            static_cast<std::int32_t>(to_size.height), 1};
    vkCmdBlitImage(cmd, from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, filter);
    transition(cmd, {to, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_BLIT_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE});
}

} // namespace

bool Presenter::present_frame(RenderSettings settings, float resolution_scale) {
    if (extent_.width == 0 || extent_.height == 0) return false; // minimised
    const std::uint32_t slot = frame_;
    // The slot's previous frame is done: its timestamps and culling counts are final.
    completed_ = renderer_.impl_->slot_stats(slot);
    std::uint32_t index = 0;
    VkResult r = vkAcquireNextImageKHR(context_.device(), swapchain_.get(), UINT64_MAX,
                                       acquired_[slot].get(), VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        resize(extent_.width, extent_.height);
        return false;
    }
    if (r != VK_SUBOPTIMAL_KHR) vk_check(r, "vkAcquireNextImageKHR");

    const auto scaled = [&](std::uint32_t side) {
        return std::max(1u,
                        static_cast<std::uint32_t>(static_cast<float>(side) * resolution_scale));
    };
    const bool reduced = blit_target_ && resolution_scale > 0.0f && resolution_scale < 1.0f;
    const VkExtent2D size =
        reduced ? VkExtent2D{scaled(extent_.width), scaled(extent_.height)} : extent_;
    settings.width = size.width;
    settings.height = size.height;
    VkCommandBuffer cmd = recorders_[slot]->begin();
    if (reduced) {
        const Image& image = renderer_.impl_->scaled_target(format_, size.width, size.height);
        RenderTarget target{image.image.get(), image.view.get(),
                            format_,           size.width,
                            size.height,       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
        renderer_.impl_->record_frame(cmd, slot, target, settings);
        blit_to_swapchain(cmd, image.image.get(), size, images_[index], extent_, blit_filter_);
    } else {
        RenderTarget target{images_[index], views_[index].get(), format_,
                            extent_.width,  extent_.height,      VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
        renderer_.impl_->record_frame(cmd, slot, target, settings);
    }
    auto wait = vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    wait.semaphore = acquired_[slot].get();
    // Where the image is first written: drawn into, or the reduced frame blitted in.
    wait.stageMask =
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    auto signal = vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    signal.semaphore = rendered_[index].get();
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    const std::uint64_t value =
        recorders_[slot]->submit(renderer_.resources(), &wait, 1, &signal, 1);
    renderer_.impl_->finish_frame(slot, value);
    frame_ = (frame_ + 1) % Renderer::kFramesInFlight;

    VkSemaphore rendered = rendered_[index].get();
    VkSwapchainKHR swapchain = swapchain_.get();
    auto pi = vk_init<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &rendered;
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain;
    pi.pImageIndices = &index;
    r = vkQueuePresentKHR(context_.queue(), &pi);
    renderer_.resources().collect_garbage();
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        resize(extent_.width, extent_.height);
        return r == VK_SUBOPTIMAL_KHR; // a suboptimal frame was still shown
    }
    vk_check(r, "vkQueuePresentKHR");
    ++presented_;
    return true;
}

} // namespace sherpa::gpu
