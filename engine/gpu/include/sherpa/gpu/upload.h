#pragma once
// Staging uploads into device-local memory. Copies are gathered, then one staging
// buffer and one command buffer carry them all; submit_and_wait() returns when the
// data is on the GPU and frees the staging memory.
#include <cstdint>
#include <span>
#include <vector>

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

class UploadBatch {
public:
    explicit UploadBatch(ResourceManager& resources) : resources_(resources) {}

    void upload_buffer(BufferHandle dst, VkDeviceSize dst_offset, const void* data,
                       VkDeviceSize size);
    // Level 0 from tightly packed texels; the other levels are made with linear
    // blits. The image ends in SHADER_READ_ONLY_OPTIMAL for fragment shaders.
    void upload_image(ImageHandle dst, const void* texels, VkDeviceSize size);
    // Every mip level given, as is (block-compressed or not; levels[0] full size,
    // each level tightly packed). levels.size() must equal the image's mip count.
    // The image ends in SHADER_READ_ONLY_OPTIMAL for fragment shaders.
    void upload_image_levels(ImageHandle dst, std::span<const std::vector<std::uint8_t>> levels);
    void submit_and_wait();

private:
    struct BufferCopy {
        BufferHandle dst;
        VkDeviceSize dst_offset, src_offset, size;
    };
    struct ImageCopy {
        ImageHandle dst;
        VkDeviceSize src_offset;
        // Empty: level 0 only, the rest blitted; else one offset per level.
        std::vector<VkDeviceSize> level_offsets;
    };
    void record_level_copies(VkCommandBuffer cmd, VkBuffer staging, const ImageCopy& c);
    VkDeviceSize stage(const void* data, VkDeviceSize size);

    ResourceManager& resources_;
    std::vector<std::uint8_t> staging_;
    std::vector<BufferCopy> buffer_copies_;
    std::vector<ImageCopy> image_copies_;
};

} // namespace sherpa::gpu
