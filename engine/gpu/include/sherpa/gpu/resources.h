#pragma once
// Buffers, images and samplers behind generation-checked handles, one dedicated
// allocation each, destroyed only after every submission that may use them has
// completed (the SubmissionTimeline that every queue submission of the engine
// signals). ResourceManager owns the buffers, the timeline and the release of what
// was retired; its ImagePool (images()) holds the images and the samplers that read
// them.
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/handle_pool.h>
#include <sherpa/gpu/submission.h>
#include <sherpa/gpu/unique_handle.h>

namespace sherpa::gpu {

struct BufferTag;
struct ImageTag;
struct SamplerTag;
using BufferHandle = Handle<BufferTag>;
using ImageHandle = Handle<ImageTag>;
using SamplerHandle = Handle<SamplerTag>;

enum class MemoryUsage {
    DeviceLocal, // GPU only; filled through staging uploads
    Upload,      // host-visible, coherent, persistently mapped (staging, per-frame data)
    Readback,    // host-visible, cached where available, persistently mapped
};

struct BufferDesc {
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    MemoryUsage memory = MemoryUsage::DeviceLocal;
    std::string name;
};

struct ImageDesc {
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    std::uint32_t width = 1, height = 1;
    std::uint32_t mip_levels = 1;
    std::uint32_t layers = 1;
    VkImageUsageFlags usage = 0;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageViewType view_type = VK_IMAGE_VIEW_TYPE_2D;
    bool layer_views = false; // also create one 2D view per array layer (shadow cascades)
    // Also a view in this (size-compatible) format, on a MUTABLE_FORMAT image: e.g. the
    // raw bytes of an sRGB colour target through an UNORM view. UNDEFINED: none.
    VkFormat alias_format = VK_FORMAT_UNDEFINED;
    std::string name;
};

struct Buffer {
    UniqueBuffer buffer;
    UniqueMemory memory;
    VkDeviceSize size = 0;
    VkDeviceSize allocation_size = 0;
    VkDeviceAddress address = 0; // 0 unless created with SHADER_DEVICE_ADDRESS usage
    void* mapped = nullptr;      // host-visible buffers only
};

struct Image {
    UniqueImage image;
    UniqueMemory memory;
    UniqueImageView view;
    std::vector<UniqueImageView> layer_views;
    UniqueImageView alias_view; // ImageDesc::alias_format
    ImageDesc desc;
    VkDeviceSize allocation_size = 0;
};

struct ResourceCounts {
    std::size_t buffers = 0, images = 0, samplers = 0, pending_destruction = 0;
    std::size_t total() const { return buffers + images + samplers + pending_destruction; }
};

// Objects the GPU may still use, each kept until the timeline completes the
// value it was retired after. Values only grow, so the oldest go first.
template <typename T> class DeferredRelease {
public:
    void retire(std::uint64_t after, T&& object) {
        pending_.emplace_back(after, std::move(object));
    }
    void release(std::uint64_t completed) {
        while (!pending_.empty() && pending_.front().first <= completed) pending_.pop_front();
    }
    void clear() { pending_.clear(); }
    std::size_t size() const { return pending_.size(); }

private:
    std::deque<std::pair<std::uint64_t, T>> pending_;
};

// Images (with their views) and samplers: what shaders sample and passes render to.
class ImagePool {
public:
    ImagePool(Context& context, const SubmissionTimeline& timeline);

    ImageHandle create(const ImageDesc& desc);
    SamplerHandle create_sampler(const VkSamplerCreateInfo& info);
    // Throw GpuError for stale or invalid handles.
    const Image& get(ImageHandle h) const { return images_.get(h); }
    VkSampler get(SamplerHandle h) const { return samplers_.get(h).get(); }
    bool alive(ImageHandle h) const { return images_.alive(h); }
    // Invalidate the handle now; the Vulkan objects go once the GPU is past every
    // submission made so far, including the one being recorded. Resets `h`.
    void destroy(ImageHandle& h);
    void destroy(SamplerHandle& h);

private:
    friend class ResourceManager; // releases, flushes and counts through these
    void release(std::uint64_t completed);
    void clear_retired();
    std::size_t pending() const { return retired_images_.size() + retired_samplers_.size(); }

    Context& context_;
    const SubmissionTimeline& timeline_;
    HandlePool<Image, ImageTag> images_{"image"};
    HandlePool<UniqueSampler, SamplerTag> samplers_{"sampler"};
    DeferredRelease<Image> retired_images_;
    DeferredRelease<UniqueSampler> retired_samplers_;
};

class ResourceManager {
public:
    explicit ResourceManager(Context& context);
    ~ResourceManager();
    ResourceManager(const ResourceManager&) = delete;
    ResourceManager& operator=(const ResourceManager&) = delete;

    BufferHandle create_buffer(const BufferDesc& desc);
    // Throws GpuError for a stale or invalid handle.
    const Buffer& get(BufferHandle h) const { return buffers_.get(h); }
    bool alive(BufferHandle h) const { return buffers_.alive(h); }
    // Invalidates the handle now; the buffer goes once the GPU is past every
    // submission made so far, including the one being recorded. Resets `h`.
    void destroy(BufferHandle& h);

    ImagePool& images() { return images_; }
    // Every engine vkQueueSubmit2 on these resources signals it (CommandRecorder::submit).
    SubmissionTimeline& timeline() { return timeline_; }

    // Frees what retired submissions no longer use, images and samplers too. Cheap;
    // call once per frame.
    void collect_garbage();
    // Waits for all work, then frees everything pending.
    void flush();
    ResourceCounts counts() const;
    std::uint64_t stale_handle_uses() const;
    Context& context() const { return context_; }

private:
    Context& context_;
    SubmissionTimeline timeline_;
    HandlePool<Buffer, BufferTag> buffers_{"buffer"};
    DeferredRelease<Buffer> retired_buffers_;
    ImagePool images_;
};

} // namespace sherpa::gpu
