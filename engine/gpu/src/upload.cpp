#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>

#include <algorithm>
#include <cstring>

namespace sherpa::gpu {

VkDeviceSize UploadBatch::stage(const void* data, VkDeviceSize size) {
    // 16-byte alignment satisfies every copy's offset rule for the formats we use.
    const VkDeviceSize offset = (staging_.size() + 15) & ~VkDeviceSize(15);
    staging_.resize(offset + size);
    std::memcpy(staging_.data() + offset, data, size);
    return offset;
}

void UploadBatch::upload_buffer(BufferHandle dst, VkDeviceSize dst_offset, const void* data,
                                VkDeviceSize size) {
    if (size == 0) return;
    const Buffer& b = resources_.get(dst);
    if (dst_offset + size > b.size) throw GpuError("upload past the end of a buffer");
    buffer_copies_.push_back({dst, dst_offset, stage(data, size), size});
}

void UploadBatch::upload_image(ImageHandle dst, const void* texels, VkDeviceSize size) {
    const Image& img = resources_.images().get(dst);
    if (img.desc.mip_levels > 1) {
        VkFormatProperties fp;
        vkGetPhysicalDeviceFormatProperties(resources_.context().physical_device(), img.desc.format,
                                            &fp);
        if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
            throw GpuError("format cannot be blitted with linear filtering for mip generation");
    }
    image_copies_.push_back({dst, stage(texels, size), {}});
}

void UploadBatch::upload_image_levels(ImageHandle dst,
                                      std::span<const std::vector<std::uint8_t>> levels) {
    const Image& img = resources_.images().get(dst);
    if (levels.empty() || levels.size() != img.desc.mip_levels)
        throw GpuError("image '" + img.desc.name + "' has " + std::to_string(img.desc.mip_levels) +
                       " mip levels but " + std::to_string(levels.size()) + " were given");
    ImageCopy c{dst, 0, {}};
    for (const auto& level : levels) {
        if (level.empty()) throw GpuError("image '" + img.desc.name + "' has an empty mip level");
        c.level_offsets.push_back(stage(level.data(), level.size()));
    }
    image_copies_.push_back(std::move(c));
}

void UploadBatch::record_level_copies(VkCommandBuffer cmd, VkBuffer staging, const ImageCopy& c) {
    const ImageDesc& d = resources_.images().get(c.dst).desc;
    VkImage image = resources_.images().get(c.dst).image.get();
    const std::uint32_t levels = static_cast<std::uint32_t>(c.level_offsets.size());
    transition(cmd,
               {image, d.aspect, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, 0, levels});
    std::vector<VkBufferImageCopy> regions(levels);
    for (std::uint32_t level = 0; level < levels; ++level) {
        VkBufferImageCopy& r = regions[level];
        r.bufferOffset = c.level_offsets[level]; // 16-byte aligned: a BC block or 4 texels
        r.imageSubresource = {d.aspect, level, 0, 1};
        // The level's real extent; block formats round up to whole blocks in the buffer.
        r.imageExtent = {std::max(1u, d.width >> level), std::max(1u, d.height >> level), 1};
    }
    vkCmdCopyBufferToImage(cmd, staging, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, levels,
                           regions.data());
    transition(cmd, {image, d.aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, 0, levels});
}

void UploadBatch::submit_and_wait() {
    if (buffer_copies_.empty() && image_copies_.empty()) return;
    Context& ctx = resources_.context();
    BufferHandle staging = resources_.create_buffer(
        {staging_.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload, "staging"});
    const Buffer& sb = resources_.get(staging);
    std::memcpy(sb.mapped, staging_.data(), staging_.size());

    CommandRecorder rec(ctx);
    VkCommandBuffer cmd = rec.begin();
    for (const BufferCopy& c : buffer_copies_) {
        VkBufferCopy region{c.src_offset, c.dst_offset, c.size};
        vkCmdCopyBuffer(cmd, sb.buffer.get(), resources_.get(c.dst).buffer.get(), 1, &region);
    }
    for (const ImageCopy& c : image_copies_) {
        if (!c.level_offsets.empty()) {
            record_level_copies(cmd, sb.buffer.get(), c);
            continue;
        }
        const Image& img = resources_.images().get(c.dst);
        const ImageDesc& d = img.desc;
        VkImage image = img.image.get();
        transition(cmd, {image, d.aspect, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                         VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT});
        VkBufferImageCopy region{};
        region.bufferOffset = c.src_offset;
        region.imageSubresource = {d.aspect, 0, 0, 1};
        region.imageExtent = {d.width, d.height, 1};
        vkCmdCopyBufferToImage(cmd, sb.buffer.get(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &region);
        // Each level is blitted from the one above, which first becomes a transfer source.
        std::int32_t w = static_cast<std::int32_t>(d.width),
                     h = static_cast<std::int32_t>(d.height);
        for (std::uint32_t level = 1; level < d.mip_levels; ++level) {
            transition(cmd,
                       {image, d.aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT, level - 1, 1});
            const std::int32_t nw = std::max(1, w / 2), nh = std::max(1, h / 2);
            VkImageBlit blit{};
            blit.srcSubresource = {d.aspect, level - 1, 0, 1};
            blit.srcOffsets[1] = {w, h, 1};
            blit.dstSubresource = {d.aspect, level, 0, 1};
            blit.dstOffsets[1] = {nw, nh, 1};
            vkCmdBlitImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            w = nw;
            h = nh;
        }
        if (d.mip_levels > 1)
            transition(cmd, {image, d.aspect, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                             VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, 0, d.mip_levels - 1});
        transition(cmd,
                   {image, d.aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, d.mip_levels - 1, 1});
    }
    // Make buffer contents visible to every later shader or index/vertex read.
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    const std::uint64_t value = rec.submit(resources_);
    resources_.timeline().wait_for(value);
    resources_.destroy(staging);
    resources_.collect_garbage();
    staging_.clear();
    buffer_copies_.clear();
    image_copies_.clear();
}

} // namespace sherpa::gpu
