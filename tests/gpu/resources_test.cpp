// Resource manager: generation-checked handles, deferred destruction, staging.
#include "rhi_test_support.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>

#include <cstring>
#include <numeric>

namespace sherpa::test {
namespace {

using gpu::BufferHandle;
using gpu::MemoryUsage;

class ResourcesTest : public RhiTest {};

TEST_F(ResourcesTest, StaleHandleIsAReportedErrorNotAReuse) {
    gpu::ResourceManager rm(context());
    BufferHandle a =
        rm.create_buffer({256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::Upload, "a"});
    const BufferHandle copy = a;
    rm.destroy(a);
    EXPECT_FALSE(a.valid()) << "destroy resets the handle it was given";
    // The slot is reused by the next buffer; the old handle must not reach it.
    BufferHandle b =
        rm.create_buffer({256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::Upload, "b"});
    EXPECT_EQ(b.index, copy.index);
    EXPECT_NE(b.generation, copy.generation);
    EXPECT_THROW(rm.get(copy), gpu::GpuError);
    EXPECT_FALSE(rm.alive(copy));
    EXPECT_TRUE(rm.alive(b));
    EXPECT_EQ(rm.stale_handle_uses(), 1u);
    rm.destroy(b);
    rm.flush();
}

TEST_F(ResourcesTest, DestructionWaitsForTheSubmissionsThatMayUseIt) {
    gpu::ResourceManager rm(context());
    const std::int64_t live_before = gpu::live_vulkan_objects();
    BufferHandle a =
        rm.create_buffer({64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::Upload, "a"});
    rm.destroy(a);
    // Nothing submitted since: the buffer waits for the submission being recorded.
    EXPECT_EQ(rm.counts().pending_destruction, 1u);
    rm.collect_garbage();
    EXPECT_EQ(rm.counts().pending_destruction, 1u);
    gpu::CommandRecorder rec(context());
    rec.begin();
    rm.timeline().wait_for(rec.submit(rm));
    rm.collect_garbage();
    EXPECT_EQ(rm.counts().pending_destruction, 0u);
    EXPECT_EQ(rm.counts().total(), 0u);
    EXPECT_EQ(gpu::live_vulkan_objects(), live_before + 1)
        << "only the recorder's command pool remains";
}

TEST_F(ResourcesTest, ImagesAndSamplersAreReleasedWithTheBuffersOfTheirSubmission) {
    gpu::ResourceManager rm(context());
    gpu::ImageDesc d;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    d.name = "img";
    gpu::ImageHandle image = rm.images().create(d);
    auto si = gpu::vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    gpu::SamplerHandle sampler = rm.images().create_sampler(si);
    EXPECT_EQ(rm.counts().images, 1u);
    EXPECT_EQ(rm.counts().samplers, 1u);
    const gpu::ImageHandle copy = image;
    rm.images().destroy(image);
    rm.images().destroy(sampler);
    EXPECT_FALSE(image.valid());
    EXPECT_FALSE(rm.images().alive(copy));
    EXPECT_THROW(rm.images().get(copy), gpu::GpuError);
    EXPECT_EQ(rm.stale_handle_uses(), 1u);
    // Retired with the submission being recorded, like buffers.
    EXPECT_EQ(rm.counts().pending_destruction, 2u);
    rm.collect_garbage();
    EXPECT_EQ(rm.counts().pending_destruction, 2u);
    gpu::CommandRecorder rec(context());
    rec.begin();
    rm.timeline().wait_for(rec.submit(rm));
    EXPECT_EQ(rm.timeline().completed_submission(), rm.timeline().last_submission());
    rm.collect_garbage();
    EXPECT_EQ(rm.counts().total(), 0u);
}

TEST_F(ResourcesTest, StagingUploadReachesDeviceLocalMemory) {
    gpu::ResourceManager rm(context());
    std::vector<std::uint32_t> data(4096);
    std::iota(data.begin(), data.end(), 7u);
    const VkDeviceSize bytes = data.size() * 4;
    BufferHandle device = rm.create_buffer(
        {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
         MemoryUsage::DeviceLocal, "dev"});
    BufferHandle readback =
        rm.create_buffer({bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback, "rb"});
    gpu::UploadBatch batch(rm);
    batch.upload_buffer(device, 0, data.data(), bytes);
    batch.submit_and_wait();

    gpu::CommandRecorder rec(context());
    VkCommandBuffer cmd = rec.begin();
    VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, rm.get(device).buffer.get(), rm.get(readback).buffer.get(), 1, &region);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    rm.timeline().wait_for(rec.submit(rm));
    EXPECT_EQ(std::memcmp(rm.get(readback).mapped, data.data(), bytes), 0);
    rm.destroy(device);
    rm.destroy(readback);
    rm.flush();
}

TEST_F(ResourcesTest, ContextRecordsDeviceCapabilities) {
    const gpu::DeviceInfo& info = context().info();
    EXPECT_FALSE(info.name.empty());
    EXPECT_GE(info.api_version, VK_API_VERSION_1_3);
    EXPECT_TRUE(context().validation().enabled());
    // Lavapipe from Mesa 25 exposes ray tracing; the flag must say what the device has.
    if (info.name.find("llvmpipe") != std::string::npos) {
        EXPECT_TRUE(info.ray_query);
        // Enabled by default (ContextOptions::ray_tracing), with its properties.
        EXPECT_TRUE(info.ray_tracing_enabled);
        EXPECT_TRUE(info.ray_query_enabled);
        EXPECT_GT(info.as_scratch_alignment, 0u);
        EXPECT_GT(info.shader_group_handle_size, 0u);
    }
}

} // namespace
} // namespace sherpa::test
