// EnvironmentMap: the build, pass by pass, in one command buffer.
#include "environment_map.h"

#include "environment_passes.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/gpu/vk_helpers.h>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <iterator>
#include <optional>
#include <vector>

namespace sherpa::render {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kSourceFormat = VK_FORMAT_R32G32B32A32_SFLOAT; // where filtered (else kFormat)
// Timestamps around the passes: EnvironmentStats::pass_ms but the lookup table's (the
// BrdfLut's own build).
constexpr std::uint32_t kStamps = std::size(EnvironmentStats{}.pass_ms);

std::uint32_t levels_of(std::uint32_t size) {
    return std::uint32_t(std::bit_width(size));
}

gpu::ImageHandle make_cube(gpu::ResourceManager& r, std::uint32_t size, std::uint32_t levels,
                           const char* name, VkImageUsageFlags extra_usage = 0) {
    gpu::ImageDesc d;
    d.format = kFormat;
    d.width = d.height = size;
    d.mip_levels = levels;
    d.layers = 6;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | extra_usage;
    d.view_type = VK_IMAGE_VIEW_TYPE_CUBE;
    d.name = name;
    return r.images().create(d);
}

std::uint64_t bytes_of(std::uint32_t size, std::uint32_t levels, std::uint32_t layers) {
    std::uint64_t b = 0;
    for (std::uint32_t l = 0; l < levels; ++l) {
        const std::uint64_t s = std::max<std::uint32_t>(size >> l, 1);
        b += s * s * layers * 8;
    }
    return b;
}

void compute_barrier(VkCommandBuffer cmd) {
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

} // namespace

EnvironmentMap::EnvironmentMap(gpu::Context& context, gpu::ResourceManager& resources,
                               const EnvironmentImage& image, const EnvironmentOptions& options,
                               const BrdfLut& lut, bool lut_built)
    : resources_(resources), lut_(lut) {
    if (!image.valid()) throw gpu::GpuError("environment image '" + image.name + "' has no texels");
    const auto start = std::chrono::steady_clock::now();
    VkDevice device = context.device();
    gpu::ImagePool& images = resources.images();

    // Sizes: the cube face a quarter of the source's width (90 degrees of 360).
    const std::uint32_t cube = std::clamp<std::uint32_t>(
        std::bit_floor(std::max<std::uint32_t>(
            options.specular_size ? options.specular_size : image.width / 4, 1)),
        kMinCube, kMaxCube);
    const bool sh9 = options.irradiance == IrradianceMode::Sh9;
    const std::uint32_t radiance_levels = levels_of(cube);
    const std::uint32_t specular_levels = levels_of(cube / kLowestLevel);
    const std::uint32_t sheen_levels = levels_of(kSheenSize / kLowestLevel);
    stats_.present = true;
    stats_.name = image.name;
    stats_.source_width = image.width;
    stats_.source_height = image.height;
    stats_.cube_size = cube;
    stats_.specular_levels = specular_levels;
    stats_.irradiance = options.irradiance;
    stats_.irradiance_size = sh9 ? 0 : kIrradianceSize;
    // SH9: projected on the CPU from the same radiance the cubes are made of.
    if (sh9) irradiance_sh_ = irradiance_sh9(project_sh9(image));
    stats_.sheen_size = kSheenSize;
    stats_.sheen_levels = sheen_levels;
    stats_.lut_size = BrdfLut::kSize;

    // Only a source wider than 4 faces needs mips (read without aliasing at a coarser
    // level); the others are read at level 0 and make none (a 1024x512 source: 10 blits
    // saved). Those are uploaded as they are, in 32-bit floats, where the device filters
    // them linearly: no conversion on the CPU. Wider ones (and every source elsewhere) go
    // in half floats (load_environment() clamped them to their range), which halves the
    // largest transient image (a 16384-wide source and its mips: 1.4 GiB, not 2.9).
    const float equirect_lod = std::max(0.0f, std::log2(float(image.width) / float(4 * cube)));
    VkFormatProperties fp{};
    vkGetPhysicalDeviceFormatProperties(context.physical_device(), kSourceFormat, &fp);
    const bool float_source =
        equirect_lod == 0.0f &&
        (fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
    gpu::ImageDesc src_desc;
    src_desc.format = float_source ? kSourceFormat : kFormat;
    src_desc.width = image.width;
    src_desc.height = image.height;
    src_desc.mip_levels = equirect_lod > 0.0f ? levels_of(std::max(image.width, image.height)) : 1;
    src_desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                     VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    src_desc.name = "environment source";
    gpu::ImageHandle source = images.create(src_desc);
    {
        gpu::UploadBatch upload(resources);
        if (float_source) {
            upload.upload_image(source, image.rgba.data(), image.rgba.size() * sizeof(float));
        } else {
            std::vector<std::uint16_t> half(image.rgba.size());
            for (std::size_t i = 0; i < half.size(); ++i)
                half[i] = glm::packHalf1x16(std::min(image.rgba[i], 65504.0f));
            upload.upload_image(source, half.data(), half.size() * sizeof(std::uint16_t));
        }
        upload.submit_and_wait();
    }
    // The specular cube's level 0 is the radiance cube's, copied (no shader pass).
    gpu::ImageHandle radiance = make_cube(resources, cube, radiance_levels, "environment radiance",
                                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    specular_ = make_cube(resources, cube, specular_levels, "environment specular",
                          VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    if (!sh9) irradiance_ = make_cube(resources, kIrradianceSize, 1, "environment irradiance");
    sheen_ = make_cube(resources, kSheenSize, sheen_levels, "environment sheen");
    stats_.bytes = bytes_of(cube, specular_levels, 6) +
                   (sh9 ? 0 : bytes_of(kIrradianceSize, 1, 6)) +
                   bytes_of(kSheenSize, sheen_levels, 6) + lut.bytes();

    auto si = gpu::vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = si.minFilter = VK_FILTER_LINEAR;
    si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    si.maxLod = VK_LOD_CLAMP_NONE;
    sampler_ = images.create_sampler(si);
    si.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT; // the equirectangular seam at -X
    gpu::SamplerHandle equirect_sampler = images.create_sampler(si);

    IblLayout layout(device, 64);
    const EquirectToCubePass to_cube(device, layout.layout());
    const CubeDownsamplePass downsample(device, layout.layout());
    const PrefilterPass ggx(device, layout.layout(), PrefilterPass::Lobe::Ggx);
    // The irradiance cube's pass only where the irradiance is a cube (SH9 has none).
    std::optional<PrefilterPass> lambert;
    if (!sh9) lambert.emplace(device, layout.layout(), PrefilterPass::Lobe::Lambert);
    const PrefilterPass charlie(device, layout.layout(), PrefilterPass::Lobe::Charlie);

    const VkImageView radiance_view = images.get(radiance).view.get();
    std::vector<gpu::UniqueImageView> views; // level views, alive until the build completes
    auto target = [&](gpu::ImageHandle h, std::uint32_t level, std::uint32_t layers) {
        views.push_back(level_view(device, images.get(h).image.get(), level, layers));
        return views.back().get();
    };
    const VkSampler linear = images.get(sampler_);

    gpu::UniqueQueryPool timestamps;
    if (context.info().timestamps)
        timestamps = gpu::create_query_pool(device, VK_QUERY_TYPE_TIMESTAMP, kStamps);
    gpu::CommandRecorder rec(context);
    VkCommandBuffer cmd = rec.begin();
    if (timestamps) {
        vkCmdResetQueryPool(cmd, timestamps.get(), 0, kStamps);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps.get(), 0);
    }
    std::uint32_t stamp = 1;
    auto mark = [&] {
        if (timestamps)
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps.get(),
                                 stamp);
        ++stamp;
    };
    std::vector<gpu::ImageHandle> built{radiance, specular_, sheen_};
    if (!sh9) built.push_back(irradiance_);
    for (gpu::ImageHandle h : built)
        gpu::transition(
            cmd, {images.get(h).image.get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    // The source was left SHADER_READ_ONLY by the upload; read it in GENERAL as well.
    gpu::transition(cmd,
                    {images.get(source).image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});

    // 1. Radiance cube level 0, then its box-filtered levels.
    to_cube.record(cmd,
                   layout.bind(images.get(equirect_sampler), images.get(source).view.get(),
                               target(radiance, 0, 6)),
                   cube, equirect_lod);
    for (std::uint32_t l = 1; l < radiance_levels; ++l) {
        compute_barrier(cmd);
        downsample.record(cmd, layout.bind(linear, radiance_view, target(radiance, l, 6)),
                          std::max(cube >> l, 1u), l - 1);
    }
    mark();
    // 2. Every prefilter reads the finished radiance cube: no barriers between.
    // Specular level 0 (roughness 0) is the sharp environment itself: a copy of the
    // radiance cube's level 0, in transfer layouts for the copy alone.
    const VkImage radiance_image = images.get(radiance).image.get();
    const VkImage specular_image = images.get(specular_).image.get();
    gpu::transition(cmd,
                    {radiance_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT, 0, 1});
    gpu::transition(cmd, {specular_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                          VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, 0, 1});
    VkImageCopy sharp{};
    sharp.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
    sharp.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
    sharp.extent = {cube, cube, 1};
    vkCmdCopyImage(cmd, radiance_image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, specular_image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &sharp);
    gpu::transition(
        cmd, {radiance_image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
              VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, 0, 1});
    gpu::transition(cmd, {specular_image, VK_IMAGE_ASPECT_COLOR_BIT,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE, 0, 1});
    compute_barrier(cmd); // the radiance cube's other levels
    for (std::uint32_t l = 1; l < specular_levels; ++l) {
        const float roughness = specular_levels > 1 ? float(l) / float(specular_levels - 1) : 0.0f;
        const std::uint32_t samples = options.specular_samples ? options.specular_samples
                                      : l == 1                 ? kSpecularSamplesFirst
                                                               : kSpecularSamples;
        ggx.record(cmd, layout.bind(linear, radiance_view, target(specular_, l, 6)), cube >> l,
                   roughness, samples, cube, radiance_levels);
    }
    mark();
    if (lambert)
        lambert->record(cmd, layout.bind(linear, radiance_view, target(irradiance_, 0, 6)),
                        kIrradianceSize, 1.0f, kIrradianceSamples, cube, radiance_levels);
    mark();
    for (std::uint32_t l = 0; l < sheen_levels; ++l) {
        // Charlie at roughness 0 is undefined: its sharpest level uses a small roughness.
        const float roughness = std::max(float(l) / float(sheen_levels - 1), 0.05f);
        charlie.record(cmd, layout.bind(linear, radiance_view, target(sheen_, l, 6)),
                       kSheenSize >> l, roughness, kSheenSamples, cube, radiance_levels);
    }
    built.erase(built.begin()); // the radiance cube is not read after the build
    for (gpu::ImageHandle h : built)
        gpu::transition(
            cmd, {images.get(h).image.get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    mark();
    resources.timeline().wait_for(rec.submit(resources));
    if (timestamps) {
        std::uint64_t ts[kStamps] = {};
        if (vkGetQueryPoolResults(device, timestamps.get(), 0, kStamps, sizeof(ts), ts,
                                  sizeof(ts[0]), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS) {
            const double ms = context.info().timestamp_period_ns * 1e-6;
            stats_.gpu_ms = double(ts[kStamps - 1] - ts[0]) * ms;
            for (std::uint32_t i = 0; i + 1 < kStamps; ++i)
                stats_.pass_ms[i] = double(ts[i + 1] - ts[i]) * ms;
        }
    }
    images.destroy(radiance);
    images.destroy(source);
    images.destroy(equirect_sampler);
    stats_.prefilter_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (lut_built) { // made for this environment, before it (SceneState::set_environment)
        stats_.pass_ms[kStamps - 1] = lut.build_gpu_ms();
        stats_.gpu_ms += lut.build_gpu_ms();
        stats_.prefilter_ms += lut.build_ms();
    }
}

EnvironmentMap::~EnvironmentMap() {
    for (gpu::ImageHandle* h : {&specular_, &irradiance_, &sheen_})
        if (h->valid()) resources_.images().destroy(*h);
    resources_.images().destroy(sampler_);
}

VkDescriptorImageInfo EnvironmentMap::specular_descriptor() const {
    const gpu::ImagePool& images = resources_.images();
    return {images.get(sampler_), images.get(specular_).view.get(),
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

void EnvironmentMap::write_descriptors(VkDevice device, VkDescriptorSet set,
                                       const BrdfLut* anisotropic_lut) const {
    const gpu::ImagePool& images = resources_.images();
    const VkSampler s = images.get(sampler_);
    const VkDescriptorImageInfo infos[] = {
        {s, images.get(specular_).view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {s, images.get(irradiance_.valid() ? irradiance_ : specular_).view.get(),
         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {s, lut_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {s, images.get(sheen_).view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {s, anisotropic_lut ? anisotropic_lut->view() : VK_NULL_HANDLE,
         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
    };
    const std::uint32_t count = anisotropic_lut ? 5 : 4;
    VkWriteDescriptorSet writes[5];
    for (std::uint32_t i = 0; i < count; ++i) {
        writes[i] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = set;
        writes[i].dstBinding = i < 4 ? 4 + i : 10;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[i].pImageInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device, count, writes, 0, nullptr);
}

} // namespace sherpa::render
