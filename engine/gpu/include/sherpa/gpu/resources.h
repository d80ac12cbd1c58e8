#pragma once
// The resource manager: buffers, images and samplers behind generation-checked
// handles, one dedicated allocation each, destroyed only after every submission
// that may use them has completed (tracked by a timeline semaphore that every
// queue submission of the engine signals).
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/handle_pool.h>
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
    ImageDesc desc;
    VkDeviceSize allocation_size = 0;
};

struct ResourceCounts {
    std::size_t buffers = 0, images = 0, samplers = 0, pending_destruction = 0;
    std::size_t total() const { return buffers + images + samplers + pending_destruction; }
};

class ResourceManager {
public:
    explicit ResourceManager(Context& context);
    ~ResourceManager();
    ResourceManager(const ResourceManager&) = delete;
    ResourceManager& operator=(const ResourceManager&) = delete;

    BufferHandle create_buffer(const BufferDesc& desc);
    ImageHandle create_image(const ImageDesc& desc);
    SamplerHandle create_sampler(const VkSamplerCreateInfo& info);

    // Throw GpuError for stale or invalid handles.
    const Buffer& get(BufferHandle h) const { return buffers_.get(h); }
    const Image& get(ImageHandle h) const { return images_.get(h); }
    VkSampler get(SamplerHandle h) const { return samplers_.get(h).get(); }
    bool alive(BufferHandle h) const { return buffers_.alive(h); }
    bool alive(ImageHandle h) const { return images_.alive(h); }

    // Invalidate the handle now; the Vulkan objects go once the GPU is past every
    // submission made so far, including the one being recorded. Resets `h`.
    void destroy(BufferHandle& h);
    void destroy(ImageHandle& h);
    void destroy(SamplerHandle& h);

    // Submission timeline: every engine vkQueueSubmit2 signals timeline() with the
    // value begin_submission() returns.
    VkSemaphore timeline() const { return timeline_.get(); }
    std::uint64_t begin_submission() { return ++submitted_; }
    std::uint64_t last_submission() const { return submitted_; }
    std::uint64_t completed_submission() const;
    void wait_for(std::uint64_t value) const;
    // Frees what retired submissions no longer use. Cheap; call once per frame.
    void collect_garbage();
    // Waits for all work, then frees everything pending.
    void flush();

    ResourceCounts counts() const;
    std::uint64_t stale_handle_uses() const {
        return buffers_.stale_uses() + images_.stale_uses() + samplers_.stale_uses();
    }
    Context& context() const { return context_; }

private:
    UniqueMemory allocate(const VkMemoryRequirements& req, MemoryUsage usage, bool device_address,
                          VkDeviceSize& allocated);

    struct Retired {
        std::uint64_t after = 0; // free once the timeline reaches this value
        std::vector<Buffer> buffers;
        std::vector<Image> images;
        std::vector<UniqueSampler> samplers;
    };
    Retired& retire_list();

    Context& context_;
    UniqueSemaphore timeline_;
    std::uint64_t submitted_ = 0;
    HandlePool<Buffer, BufferTag> buffers_{"buffer"};
    HandlePool<Image, ImageTag> images_{"image"};
    HandlePool<UniqueSampler, SamplerTag> samplers_{"sampler"};
    std::vector<Retired> retired_;
};

} // namespace sherpa::gpu
