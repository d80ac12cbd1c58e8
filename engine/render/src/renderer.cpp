// The Renderer over its SceneState and FrameRecorder: construction, scene load/unload,
// the frame slots (FrameSlots: per-slot resources, set 1, waiting), and the recorder's
// statistics of completed frames (the targets and readback: render_targets.cpp).
#include "frame_recorder.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

FrameSlots::FrameSlots(SceneState& scene_state) : SceneStateRefs(scene_state) {
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
        auto slot = std::make_unique<FrameSlot>(context);
        slot->frame_data =
            resources->create_buffer({sizeof(GPUFrameData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                      gpu::MemoryUsage::Upload, "frame data"});
        slot->timestamps =
            gpu::create_query_pool(context.device(), VK_QUERY_TYPE_TIMESTAMP, kTimestampCount);
        if (context.info().pipeline_statistics)
            slot->statistics = gpu::create_query_pool(
                context.device(), VK_QUERY_TYPE_PIPELINE_STATISTICS, 1,
                VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT |
                    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
                    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT |
                    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
                    VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT);
        slots_.push_back(std::move(slot));
    }
    create_frame_sets();
}

FrameSlots::~FrameSlots() {
    for (auto& slot : slots_) {
        resources->destroy(slot->frame_data);
        resources->destroy(slot->lines);
        resources->destroy(slot->cull_ids);
        resources->destroy(slot->cull_readback);
        resources->destroy(slot->pose);
        resources->destroy(slot->cull_objects);
    }
    slots_.clear();
    resources->destroy(no_materials_);
}

std::uint32_t FrameSlots::take() {
    const std::uint32_t index = next_slot_;
    next_slot_ = (next_slot_ + 1) % kFramesInFlight;
    return index;
}

void FrameSlots::create_frame_sets() {
    VkDevice device = context.device();
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorSetLayoutBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        // The environment's maps (shaders/include/ibl.glsl): partially bound, so a
        // renderer without an environment binds (and holds) nothing there.
        {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {6, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {7, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        // The material extension blocks (shaders/include/material_ext.glsl): partially
        // bound, so a scene whose materials use no extension binds (and holds) nothing.
        {8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        // The transmission background (TransmissionPass, shaders/include/refraction.glsl):
        // partially bound, written only for scenes with a transmissive material.
        {9, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        // KHR_materials_anisotropy's split-sum table (ibl.glsl): partially bound, written
        // only while an environment and a scene with an anisotropic material are loaded.
        {10, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    };
    // Bindings 4 and on are partially bound (above).
    VkDescriptorBindingFlags binding_flags[std::size(bindings)] = {};
    for (std::size_t i = 4; i < std::size(bindings); ++i)
        binding_flags[i] = VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT;
    auto flags_info = gpu::vk_init<VkDescriptorSetLayoutBindingFlagsCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO);
    flags_info.bindingCount = static_cast<std::uint32_t>(std::size(binding_flags));
    flags_info.pBindingFlags = binding_flags;
    frame_layout_ = gpu::create_descriptor_set_layout(
        device, bindings, "vkCreateDescriptorSetLayout(frame)", 0, &flags_info);
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kFramesInFlight},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * kFramesInFlight},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 7 * kFramesInFlight}};
    frame_pool_ = gpu::create_descriptor_pool(device, kFramesInFlight, sizes,
                                              "vkCreateDescriptorPool(frame)");
    no_materials_ =
        resources->create_buffer({sizeof(GPUMaterialExtra), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  gpu::MemoryUsage::Upload, "no materials"});
    const VkDescriptorSetLayout layout = frame_layout_.get();
    for (auto& slot : slots_) {
        auto ai = gpu::vk_init<VkDescriptorSetAllocateInfo>(
            VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        ai.descriptorPool = frame_pool_.get();
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        gpu::vk_check(vkAllocateDescriptorSets(device, &ai, &slot->set),
                      "vkAllocateDescriptorSets(frame)");
    }
}

// Points the slot's set at its frame data and the current scene's materials. The
// slot's previous frame has completed, so the set is not in use.
void FrameSlots::bind_frame_set(FrameSlot& slot, const VkDescriptorImageInfo& shadow) {
    if (slot.set_environment != state.environment_generation) {
        // Without an environment the old maps' descriptors stay, never read (ibl.glsl
        // checks frame.environment.y, 0 then): the bindings are partially bound.
        if (environment)
            environment->write_descriptors(context.device(), slot.set, state.anisotropic_lut.get());
        slot.set_environment = state.environment_generation;
    }
    if (slot.set_generation == state.generation) return;
    const VkBuffer none = resources->get(no_materials_).buffer.get();
    const VkDescriptorBufferInfo infos[] = {
        {resources->get(slot.frame_data).buffer.get(), 0, sizeof(GPUFrameData)},
        {scene ? scene->materials().buffer() : none, 0, VK_WHOLE_SIZE},
        {scene ? scene->materials().extras_buffer() : none, 0, VK_WHOLE_SIZE},
    };
    VkWriteDescriptorSet writes[4];
    writes[3] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[3].dstSet = slot.set;
    writes[3].dstBinding = 3;
    writes[3].descriptorCount = 1;
    writes[3].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[3].pImageInfo = &shadow;
    for (std::uint32_t i = 0; i < 3; ++i) {
        writes[i] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = slot.set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType =
            i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(context.device(), 4, writes, 0, nullptr);
    // Without extension blocks the old descriptor stays, never read (a material reads
    // its blocks only where GPUMaterialExtra::extensions names one).
    if (const VkBuffer ext = scene ? scene->materials().extensions_buffer() : VK_NULL_HANDLE) {
        const VkDescriptorBufferInfo info{ext, 0, VK_WHOLE_SIZE};
        auto write = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        write.dstSet = slot.set;
        write.dstBinding = 8;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        write.pBufferInfo = &info;
        vkUpdateDescriptorSets(context.device(), 1, &write, 0, nullptr);
    }
    slot.set_generation = state.generation;
}

FrameRecorder::FrameRecorder(SceneState& scene_state)
    : SceneStateRefs(scene_state), options(scene_state.options), culling(context, *resources),
      pose_(*resources), shadows_(context, *resources, options.shadow_resolution),
      slots_(scene_state), targets_(*resources) {
    transmission_ = std::make_unique<TransmissionPass>(context, *resources, bindless->layout(),
                                                       slots_.layout());
}

FrameRecorder::~FrameRecorder() {
    context.wait_idle();
    culling.reset();
    comparison_.reset();
    pipelines_.clear();
}

Pipelines& FrameRecorder::pipelines_for(VkFormat format) {
    auto& p = pipelines_[format];
    if (!p) p = std::make_unique<Pipelines>(context, bindless->layout(), slots_.layout(), format);
    return *p;
}

void FrameRecorder::scene_loaded(const scene::Scene& source) {
    culling.build(*scene);
    pose_.build(source, *scene);
    shadows_.invalidate();
    // Meshes that skin or morph join the TLAS in the file's default pose, on load.
    if (acceleration && acceleration->posed()) {
        FrameSlot& slot = slots_[slots_.next()];
        slots_.wait(slot);
        rays_.pose_acceleration(slot, FrameRequest{});
    }
}

void FrameRecorder::scene_unloading() {
    // Frames in flight may still read the scene's buffers and textures: wait for
    // them, so that the bindless slots the scene gives back can be reused at once.
    if (transmission_) transmission_->release();
    for (auto& slot : slots_) {
        slots_.wait(*slot);
        // Sized for the scene's instances: it goes with the scene.
        resources->destroy(slot->cull_ids);
        slot->cull_ids_capacity = 0;
        resources->destroy(slot->cull_readback);
        slot->cull_readback_capacity = 0;
        slot->culling.count = 0;
        slot->posed = false;
        slot->pose_generation = 0;
        slot->pose_written.reset();
        resources->destroy(slot->pose); // sized for the scene's instances and joints
        slot->pose_capacity = 0;
        resources->destroy(slot->cull_objects);
        slot->cull_objects_capacity = 0;
    }
    culling.reset();
    pose_.reset();
    shadows_.invalidate();
}

void FrameRecorder::count_target_bytes(ResidentStats& out) const {
    out.transmission_target_bytes = transmission_->bytes();
    out.render_target_bytes =
        shadows_.bytes() + targets_.bytes() + background_.bytes() + out.transmission_target_bytes;
}

void FrameRecorder::wait_all(bool environment_goes) {
    slots_.wait_all();
    if (environment_goes) background_.release();
}

void FrameSlots::wait_all() {
    for (auto& slot : slots_) wait(*slot);
}

void FrameSlots::wait(FrameSlot& slot) {
    if (slot.submission) resources->timeline().wait_for(slot.submission);
}

FrameStats render_offscreen(FrameRecorder& frames, gpu::ResourceManager& resources,
                            const FrameRequest& settings, std::vector<std::uint8_t>* rgba) {
    if (settings.width == 0 || settings.height == 0 || settings.width > 16384 ||
        settings.height > 16384)
        throw gpu::GpuError("render size " + std::to_string(settings.width) + "x" +
                            std::to_string(settings.height) + " is out of range");
    if (settings.renderer == RendererKind::RayTraced) {
        // The shadow-error view compares with the rasterizer's cascades at this camera:
        // its shadow view is drawn first (cascades and frame constants in that slot).
        const std::uint32_t raster_slot = frames.slots().next();
        if (settings.view == DebugView::ShadowError) {
            frames.rays().check_rt(settings); // refused before the raster frame
            FrameRequest raster = settings;
            raster.renderer = RendererKind::Raster;
            raster.view = DebugView::Shadow;
            render_offscreen(frames, resources, raster, nullptr);
        }
        return frames.rays().render_rt(settings, rgba, raster_slot);
    }
    if (!raster_view(settings.view))
        throw gpu::GpuError("the rasterizer does not draw view '" +
                            std::string(to_string(settings.view)) + "' (rays only: --renderer rt)");
    FrameSlots& slots = frames.slots();
    RenderTargets& targets = frames.targets();
    const std::uint32_t index = slots.take();
    FrameSlot& slot = slots[index];
    slots.wait(slot);
    const gpu::RenderTarget target = targets.offscreen(settings.width, settings.height);
    VkCommandBuffer cmd = slot.recorder.begin();
    frames.record_frame(cmd, index, target, settings);
    if (rgba) targets.record_readback(cmd, settings.width, settings.height);
    const std::uint64_t value = slot.recorder.submit(resources);
    slots.finish(index, value);
    FrameStats stats = frames.slot_stats(index);
    if (rgba) targets.read_offscreen(*rgba, settings.width, settings.height);
    resources.collect_garbage();
    return stats;
}

void FrameSlots::finish(std::uint32_t slot, std::uint64_t submission) {
    slots_.at(slot)->submission = submission;
    slots_.at(slot)->has_results = true;
}

FrameStats FrameRecorder::slot_stats(std::uint32_t index) {
    FrameSlot& slot = slots_[index];
    slots_.wait(slot);
    return read_stats(slot);
}

FrameStats FrameRecorder::read_stats(FrameSlot& slot) {
    FrameStats s;
    if (!slot.has_results) return s;
    if (slot.ray_traced) return rays_.read_rt_stats(slot);
    s.shadows_rendered = slot.shadows_rendered;
    s.draw_calls = slot.draw_calls;
    culling.read_stats(slot, scene.get(), s);
    if (context.info().timestamps) {
        std::uint64_t ts[kTimestampCount] = {};
        gpu::vk_check(vkGetQueryPoolResults(context.device(), slot.timestamps.get(), 0,
                                            kTimestampCount, sizeof(ts), ts, sizeof(std::uint64_t),
                                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                      "vkGetQueryPoolResults(timestamps)");
        const double ns = context.info().timestamp_period_ns;
        for (std::uint32_t i = 0; i + 1 < kTimestampCount; ++i)
            s.passes.push_back({kPassNames[i], double(ts[i + 1] - ts[i]) * ns * 1e-6});
        s.gpu_ms = double(ts[kTimestampCount - 1] - ts[0]) * ns * 1e-6;
    }
    if (slot.statistics) {
        std::uint64_t v[5] = {};
        gpu::vk_check(vkGetQueryPoolResults(context.device(), slot.statistics.get(), 0, 1,
                                            sizeof(v), v, sizeof(v),
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

// The public face: a load goes to the scene state, then the recorder; frames to the recorder.

Renderer::Renderer(gpu::Context& context, const RendererOptions& options)
    : context_(context), resources_(std::make_unique<gpu::ResourceManager>(context)),
      scene_(std::make_unique<SceneState>(context, *resources_, options)),
      frames_(std::make_unique<FrameRecorder>(*scene_)) {}

Renderer::~Renderer() {
    frames_.reset(); // waits for the device; before the scene its frames read
    scene_.reset();
}

void Renderer::load(const scene::Scene& scene, const SceneSetup& setup) {
    unload();
    SceneState& s = *scene_;
    s.load(scene,
           std::make_unique<GpuScene>(*resources_, s.bindless, scene, s.options.textures,
                                      setup.streams, setup.missing_textures),
           setup);
    frames_->scene_loaded(scene);
}

void Renderer::load(const scene::Scene& scene,
                    std::shared_ptr<const tex::PreparedTextureSet> textures,
                    const SceneSetup& setup) {
    unload();
    SceneState& s = *scene_;
    s.load(scene,
           std::make_unique<GpuScene>(*resources_, s.bindless, scene, std::move(textures),
                                      setup.streams, setup.missing_textures),
           setup);
    frames_->scene_loaded(scene);
}

void Renderer::set_hidden_nodes(std::shared_ptr<const std::vector<bool>> hidden) {
    scene_->setup.hidden_nodes = std::move(hidden);
}

void Renderer::unload() {
    // Frames in flight may still read the scene's buffers and textures: the recorder
    // waits for them, so that the bindless slots the scene gives back can be reused at once.
    frames_->scene_unloading();
    scene_->unload();
    resources_->collect_garbage();
}

const GpuScene* Renderer::scene() const {
    return scene_->gpu.get();
}

FrameStats Renderer::render(const FrameRequest& settings, std::vector<std::uint8_t>* rgba) {
    return render_offscreen(*frames_, *resources_, settings, rgba);
}

const scene::RingHistory<CullFrame>& Renderer::cull_history() const {
    return frames_->cull_history();
}

gpu::ResourceManager& Renderer::resources() {
    return *resources_;
}

gpu::Context& Renderer::context() {
    return context_;
}

FrameRecorder& Renderer::frames() {
    return *frames_;
}

ResidentStats Renderer::resident() const {
    ResidentStats out;
    out.acceleration =
        scene_->acceleration && scene_->gpu ? &scene_->acceleration->stats() : nullptr;
    out.environment = scene_->environment ? scene_->environment->stats() : EnvironmentStats{};
    if (const BrdfLut* a = scene_->anisotropic_lut.get()) {
        out.environment.anisotropy_lut_bytes = a->bytes();
        out.environment.bytes += a->bytes();
        out.environment.anisotropy_lut_gpu_ms = a->build_gpu_ms();
    }
    frames_->count_target_bytes(out);
    const EmissiveLights& e = scene_->emissive;
    out.emissive = {e.triangles.size(), e.textures_read, e.textures_reused, scene_->emissive_ms,
                    e.warnings};
    return out;
}

} // namespace sherpa::render
