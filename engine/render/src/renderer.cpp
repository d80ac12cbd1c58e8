#include "frame_slot.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/gpu_structs.h>

#include <cstring>

namespace sherpa::gpu {

Renderer::Renderer(Context& context, const RendererOptions& options)
    : context_(context), options_(options), resources_(std::make_unique<ResourceManager>(context)),
      lighting_(std::make_unique<Lighting>()) {
    bindless_ = std::make_unique<BindlessTable>(*resources_);
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
        auto slot = std::make_unique<FrameSlot>(context_);
        slot->frame_data =
            resources_->create_buffer({sizeof(GPUFrameData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                       MemoryUsage::Upload, "frame data"});
        auto qi = vk_init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
        qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qi.queryCount = kTimestampCount;
        VkQueryPool pool = VK_NULL_HANDLE;
        vk_check(vkCreateQueryPool(context_.device(), &qi, nullptr, &pool), "vkCreateQueryPool");
        slot->timestamps = UniqueQueryPool(context_.device(), pool);
        if (context_.info().pipeline_statistics) {
            qi.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
            qi.queryCount = 1;
            qi.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT |
                                    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
                                    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT |
                                    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
                                    VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
            vk_check(vkCreateQueryPool(context_.device(), &qi, nullptr, &pool),
                     "vkCreateQueryPool");
            slot->statistics = UniqueQueryPool(context_.device(), pool);
        }
        slots_.push_back(std::move(slot));
    }
    init_shadow_map();
    create_frame_sets();
}

void Renderer::create_frame_sets() {
    VkDevice device = context_.device();
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorSetLayoutBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    };
    auto lci = vk_init<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    lci.bindingCount = 4;
    lci.pBindings = bindings;
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    vk_check(vkCreateDescriptorSetLayout(device, &lci, nullptr, &layout),
             "vkCreateDescriptorSetLayout(frame)");
    frame_layout_ = UniqueDescriptorSetLayout(device, layout);
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kFramesInFlight},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * kFramesInFlight},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kFramesInFlight}};
    auto pci = vk_init<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    pci.maxSets = kFramesInFlight;
    pci.poolSizeCount = 3;
    pci.pPoolSizes = sizes;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    vk_check(vkCreateDescriptorPool(device, &pci, nullptr, &pool), "vkCreateDescriptorPool(frame)");
    frame_pool_ = UniqueDescriptorPool(device, pool);
    no_materials_ =
        resources_->create_buffer({sizeof(GPUMaterialExtra), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                   MemoryUsage::Upload, "no materials"});
    for (auto& slot : slots_) {
        auto ai =
            vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        ai.descriptorPool = pool;
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        vk_check(vkAllocateDescriptorSets(device, &ai, &slot->set),
                 "vkAllocateDescriptorSets(frame)");
    }
}

// Points the slot's set at its frame data and the current scene's materials. The
// slot's previous frame has completed, so the set is not in use.
void Renderer::bind_frame_set(FrameSlot& slot) {
    if (slot.set_generation == scene_generation_) return;
    const VkBuffer none = resources_->get(no_materials_).buffer.get();
    const VkDescriptorBufferInfo infos[] = {
        {resources_->get(slot.frame_data).buffer.get(), 0, sizeof(GPUFrameData)},
        {scene_ ? scene_->materials_buffer() : none, 0, VK_WHOLE_SIZE},
        {scene_ ? scene_->material_extras_buffer() : none, 0, VK_WHOLE_SIZE},
    };
    const VkDescriptorImageInfo shadow{resources_->get(shadow_sampler_),
                                       resources_->get(shadow_map_).view.get(),
                                       VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet writes[4];
    writes[3] = vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[3].dstSet = slot.set;
    writes[3].dstBinding = 3;
    writes[3].descriptorCount = 1;
    writes[3].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[3].pImageInfo = &shadow;
    for (std::uint32_t i = 0; i < 3; ++i) {
        writes[i] = vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = slot.set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType =
            i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(context_.device(), 4, writes, 0, nullptr);
    slot.set_generation = scene_generation_;
}

Renderer::~Renderer() {
    context_.wait_idle();
    if (culling_) resources_->destroy(culling_->identity);
    culling_.reset();
    scene_.reset();
    for (auto& slot : slots_) {
        resources_->destroy(slot->frame_data);
        resources_->destroy(slot->lines);
        resources_->destroy(slot->cull_ids);
        resources_->destroy(slot->cull_readback);
    }
    slots_.clear();
    resources_->destroy(color_);
    resources_->destroy(depth_);
    resources_->destroy(shadow_map_);
    resources_->destroy(shadow_sampler_);
    resources_->destroy(readback_);
    resources_->destroy(no_materials_);
    pipelines_.clear();
    bindless_.reset();
    resources_->flush();
}

void Renderer::init_shadow_map() {
    ImageDesc d;
    d.format = kDepthFormat;
    d.width = d.height = options_.shadow_resolution;
    d.layers = kMaxCascades;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
              VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    d.view_type = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    d.layer_views = true;
    d.name = "shadow cascades";
    shadow_map_ = resources_->create_image(d);

    auto si = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = si.minFilter = VK_FILTER_LINEAR; // 2x2 percentage-closer filtering per tap
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    si.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE; // outside every cascade: lit
    si.compareEnable = VK_TRUE;
    si.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    shadow_sampler_ = resources_->create_sampler(si);
    const Image& img = resources_->get(shadow_map_);

    // The descriptor names a read-only layout from the start, so the map is cleared
    // (fully lit) and put in that layout before any frame can sample it.
    CommandRecorder rec(context_);
    VkCommandBuffer cmd = rec.begin();
    transition(cmd,
               {img.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkClearDepthStencilValue one{1.0f, 0};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, kMaxCascades};
    vkCmdClearDepthStencilImage(cmd, img.image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1,
                                &range);
    transition(cmd,
               {img.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    resources_->wait_for(rec.submit(*resources_));
}

Pipelines& Renderer::pipelines_for(VkFormat format) {
    auto& p = pipelines_[format];
    if (!p)
        p = std::make_unique<Pipelines>(context_, bindless_->layout(), frame_layout_.get(), format);
    return *p;
}

void Renderer::load(const Scene& scene, StreamPolicy policy) {
    unload();
    scene_ = std::make_unique<GpuScene>(*resources_, *bindless_, scene, options_.textures, policy);
    adopt(scene);
}

void Renderer::load(const Scene& scene, std::shared_ptr<const tex::PreparedTextureSet> textures,
                    StreamPolicy policy) {
    unload();
    scene_ = std::make_unique<GpuScene>(*resources_, *bindless_, scene, std::move(textures), policy,
                                        options_.textures.missing);
    adopt(scene);
}

void Renderer::adopt(const Scene& scene) {
    build_culling();
    Scene& info = lighting_->info;
    info.bounds = scene_->bounds().valid() ? scene_->bounds() : scene.bounds;
    info.cameras = scene.cameras;
    info.placed_cameras = scene.placed_cameras;
    info.lights = scene.lights;
    info.placed_lights = scene.placed_lights;
    ++scene_generation_;
    shadow_key_.clear();
}

void Renderer::unload() {
    // Frames in flight may still read the scene's buffers and textures: wait for
    // them, so that the bindless slots the scene gives back can be reused at once.
    for (auto& slot : slots_) {
        wait_slot(*slot);
        // Sized for the scene's instances: it goes with the scene.
        resources_->destroy(slot->cull_ids);
        slot->cull_ids_capacity = 0;
        resources_->destroy(slot->cull_readback);
        slot->cull_readback_capacity = 0;
        slot->pass_count = 0;
    }
    cascade_stats_.clear();
    if (culling_) resources_->destroy(culling_->identity);
    culling_.reset();
    scene_.reset();
    ++scene_generation_; // frame sets must stop naming the freed material buffers
    lighting_->info = Scene{};
    shadow_key_.clear();
    resources_->collect_garbage();
}

void Renderer::wait_for_slot(std::uint32_t slot) {
    wait_slot(*slots_.at(slot));
}

void Renderer::wait_slot(FrameSlot& slot) {
    if (slot.submission) resources_->wait_for(slot.submission);
}

void Renderer::ensure_depth(std::uint32_t width, std::uint32_t height) {
    if (depth_.valid()) {
        const ImageDesc& d = resources_->get(depth_).desc;
        if (d.width == width && d.height == height) return;
        resources_->destroy(depth_);
    }
    ImageDesc d;
    d.format = kDepthFormat;
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    d.name = "depth";
    depth_ = resources_->create_image(d);
}

void Renderer::ensure_offscreen(std::uint32_t width, std::uint32_t height) {
    if (color_.valid()) {
        const ImageDesc& d = resources_->get(color_).desc;
        if (d.width == width && d.height == height) return;
        resources_->destroy(color_);
        resources_->destroy(readback_);
    }
    ImageDesc d;
    d.format = kOffscreenFormat;
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.name = "offscreen colour";
    color_ = resources_->create_image(d);
    readback_ = resources_->create_buffer({VkDeviceSize(width) * height * 4,
                                           VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback,
                                           "readback"});
}

std::uint64_t Renderer::render_target_bytes() const {
    std::uint64_t bytes = 0;
    for (ImageHandle h : {color_, depth_, shadow_map_})
        if (h.valid()) bytes += resources_->get(h).allocation_size;
    return bytes;
}

FrameStats Renderer::render(const RenderSettings& settings, std::vector<std::uint8_t>* rgba) {
    if (settings.width == 0 || settings.height == 0 || settings.width > 16384 ||
        settings.height > 16384)
        throw GpuError("render size " + std::to_string(settings.width) + "x" +
                       std::to_string(settings.height) + " is out of range");
    const std::uint32_t index = next_slot_;
    next_slot_ = (next_slot_ + 1) % kFramesInFlight;
    FrameSlot& slot = *slots_[index];
    wait_slot(slot);
    ensure_offscreen(settings.width, settings.height);
    const Image& color = resources_->get(color_);

    VkCommandBuffer cmd = slot.recorder.begin();
    RenderTarget target{color.image.get(), color.view.get(), kOffscreenFormat,
                        settings.width,    settings.height,  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    record_frame(cmd, index, target, settings);
    if (rgba) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {settings.width, settings.height, 1};
        vkCmdCopyImageToBuffer(cmd, color.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               resources_->get(readback_).buffer.get(), 1, &region);
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    }
    const std::uint64_t value = slot.recorder.submit(*resources_);
    finish_frame(index, value);
    FrameStats stats = slot_stats(index);
    if (rgba) {
        const Buffer& rb = resources_->get(readback_);
        rgba->resize(std::size_t(settings.width) * settings.height * 4);
        std::memcpy(rgba->data(), rb.mapped, rgba->size());
    }
    resources_->collect_garbage();
    return stats;
}

void Renderer::finish_frame(std::uint32_t slot, std::uint64_t submission) {
    slots_.at(slot)->submission = submission;
    slots_.at(slot)->has_results = true;
}

FrameStats Renderer::slot_stats(std::uint32_t index) {
    FrameSlot& slot = *slots_.at(index);
    wait_slot(slot);
    return read_stats(slot);
}

FrameStats Renderer::read_stats(FrameSlot& slot) {
    FrameStats s;
    if (!slot.has_results) return s;
    s.shadows_rendered = slot.shadows_rendered;
    s.draw_calls = slot.draw_calls;
    read_cull_stats(slot, s);
    if (context_.info().timestamps) {
        std::uint64_t ts[kTimestampCount] = {};
        vk_check(vkGetQueryPoolResults(context_.device(), slot.timestamps.get(), 0, kTimestampCount,
                                       sizeof(ts), ts, sizeof(std::uint64_t),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                 "vkGetQueryPoolResults(timestamps)");
        const double ns = context_.info().timestamp_period_ns;
        for (std::uint32_t i = 0; i + 1 < kTimestampCount; ++i)
            s.passes.push_back({kPassNames[i], double(ts[i + 1] - ts[i]) * ns * 1e-6});
        s.gpu_ms = double(ts[kTimestampCount - 1] - ts[0]) * ns * 1e-6;
    }
    if (slot.statistics) {
        std::uint64_t v[5] = {};
        vk_check(vkGetQueryPoolResults(context_.device(), slot.statistics.get(), 0, 1, sizeof(v), v,
                                       sizeof(v),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                 "vkGetQueryPoolResults(statistics)");
        // Results come in the order of the statistic bits.
        s.input_primitives = v[0];
        s.vertex_invocations = v[1];
        s.clipping_invocations = v[2];
        s.clipping_primitives = v[3];
        s.fragment_invocations = v[4];
    }
    return s;
}

} // namespace sherpa::gpu
