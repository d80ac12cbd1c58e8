#pragma once
// KHR_materials_transmission's background (transmission_pass.cpp): before the camera's
// rendering, the opaque and masked surfaces of the lit view, transmissive materials
// left out, as linear radiance (RGBA16F, coverage in alpha) into a mip-mapped target of
// the frame's size; its levels are made by blits. Transmissive surfaces sample it along
// their refracted ray at a level from their roughness and ior
// (shaders/include/refraction.glsl, set 1 binding 9). A scene without a transmissive
// material has no target and no pass: active() is false and nothing is allocated.
#include "frame_context.h"

#include <memory>

namespace sherpa::render {

class TransmissionPass {
public:
    TransmissionPass(gpu::Context& context, gpu::ResourceManager& resources,
                     VkDescriptorSetLayout textures_layout, VkDescriptorSetLayout frame_layout);
    ~TransmissionPass();
    TransmissionPass(const TransmissionPass&) = delete;
    TransmissionPass& operator=(const TransmissionPass&) = delete;

    // The lit view of a scene with a material whose transmission can be non-zero.
    static bool active(const FrameContext& f);
    // Before the frame's descriptor sets are bound: the target at the frame's size,
    // written to the slot's set (binding 9). Frees the target where not active.
    void prepare(FrameContext& f);
    // After the shadow maps, before the camera's rendering: draws and mips the target.
    void record(FrameContext& f);
    // GPU bytes of the target and its depth (0 where the scene has no transmission).
    std::uint64_t bytes() const;
    void release(); // the scene is unloaded

private:
    void ensure_target(FrameContext& f);

    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    VkDescriptorSetLayout textures_layout_, frame_layout_;
    std::unique_ptr<Pipelines> pipelines_; // forward.frag with TRANSMISSION_BACKGROUND
    gpu::ImageHandle color_, depth_;
    // Level 0 alone: what rendering writes (an attachment view has one level). Not in
    // the pool, so a resize waits for the device before it goes.
    gpu::UniqueImageView level0_;
    gpu::SamplerHandle sampler_;
    std::uint32_t width_ = 0, height_ = 0, levels_ = 0;
};

} // namespace sherpa::render
