#include "environment_lut.h"

#include "environment_passes.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

#include <chrono>

namespace sherpa::render {

BrdfLut::BrdfLut(gpu::Context& context, gpu::ResourceManager& resources, bool anisotropic)
    : resources_(resources), anisotropic_(anisotropic) {
    const auto start = std::chrono::steady_clock::now();
    VkDevice device = context.device();
    gpu::ImagePool& images = resources.images();
    gpu::ImageDesc d;
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.width = anisotropic ? kAnisotropicNDotV : kSize;
    d.height = anisotropic ? kAnisotropicRoughness : kSize;
    d.layers = anisotropic ? kAnisotropicLayers : 1;
    if (anisotropic) d.view_type = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    d.name = anisotropic ? "environment anisotropic brdf lut" : "environment brdf lut";
    image_ = images.create(d);

    IblLayout layout(device, 1);
    const BrdfLutPass pass(device, layout.layout(), anisotropic);
    const gpu::UniqueImageView target =
        level_view(device, images.get(image_).image.get(), 0, d.layers);

    gpu::UniqueQueryPool timestamps;
    if (context.info().timestamps)
        timestamps = gpu::create_query_pool(device, VK_QUERY_TYPE_TIMESTAMP, 2);
    gpu::CommandRecorder rec(context);
    VkCommandBuffer cmd = rec.begin();
    const VkImage image = images.get(image_).image.get();
    if (timestamps) {
        vkCmdResetQueryPool(cmd, timestamps.get(), 0, 2);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps.get(), 0);
    }
    gpu::transition(cmd,
                    {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    pass.record(cmd, layout.bind(VK_NULL_HANDLE, VK_NULL_HANDLE, target.get()), d.width,
                anisotropic ? kAnisotropicSamples : kSamples, d.layers);
    gpu::transition(cmd,
                    {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    if (timestamps)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps.get(), 1);
    resources.timeline().wait_for(rec.submit(resources));
    if (timestamps) {
        std::uint64_t ts[2] = {};
        if (vkGetQueryPoolResults(device, timestamps.get(), 0, 2, sizeof(ts), ts, sizeof(ts[0]),
                                  VK_QUERY_RESULT_64_BIT) == VK_SUCCESS)
            build_gpu_ms_ = double(ts[1] - ts[0]) * context.info().timestamp_period_ns * 1e-6;
    }
    build_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

BrdfLut::~BrdfLut() {
    resources_.images().destroy(image_);
}

VkImageView BrdfLut::view() const {
    return resources_.images().get(image_).view.get();
}

} // namespace sherpa::render
