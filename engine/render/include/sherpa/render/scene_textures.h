#pragma once
// A scene's textures on the GPU: the texture pipeline's prepared levels (BC7 sRGB
// for colour, BC7 UNORM for data, BC5 for normal maps, or RGBA8 where the device
// cannot sample BC) uploaded as they are with their full mip chains through one
// staging batch, registered in the bindless table, plus the sampler objects the
// glTF samplers map to. Preparation (decode, mips, compression, cache) is CPU
// work that may run on any thread before the upload: tex::prepare_scene_textures()
// for the device's texture_target().
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/gpu/bindless.h>
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/render/load_settings.h>
#include <sherpa/scene/scene.h>
#include <sherpa/texture/texture_pipeline.h>
#include <sherpa/texture/texture_target.h>

namespace sherpa::render {

// What textures are prepared for on `device`: BC where it samples BC7/BC5, BC7
// decoded to RGBA8 where it is a CPU device and `settings` does not keep the blocks.
tex::TextureTarget texture_target(const gpu::DeviceInfo& device, const TextureSettings& settings);
// The texture pipeline's options from `settings` (cache, BC7 level, progress, cancel;
// force_rgba8 turns BC off whatever the target samples).
tex::PipelineOptions texture_pipeline_options(const TextureSettings& settings);

// One prepared texture on the GPU.
struct GpuTexture {
    gpu::ImageHandle image;
    std::uint32_t slot = scene::kTextureSentinel; // bindless slot; sentinel when it failed
    std::uint32_t mip_levels = 0;
    std::uint64_t bytes = 0; // device memory of the image
};

class SceneTextures {
public:
    // Uploads every texture of `prepared` (prepared for `scene`) that did not fail.
    SceneTextures(gpu::ResourceManager& resources, gpu::BindlessTable& table,
                  const scene::Scene& scene,
                  std::shared_ptr<const tex::PreparedTextureSet> prepared,
                  MissingTextures missing = MissingTextures::Checker);
    ~SceneTextures();
    SceneTextures(const SceneTextures&) = delete;
    SceneTextures& operator=(const SceneTextures&) = delete;

    // The pipeline's records (state, hash, PSNR, timings, bytes) for inspection;
    // gpu()[i] is records()[i] on the GPU. Levels may have been released after upload.
    const tex::PreparedTextureSet& prepared() const { return *prepared_; }
    const std::vector<tex::PreparedTexture>& records() const { return prepared_->textures; }
    const std::vector<GpuTexture>& gpu() const { return gpu_; }
    std::span<const std::uint32_t> slots() const { return slots_; }

    // The material's GPU record with texture fields resolved to bindless slots, absent
    // textures to the default textures, and failed (missing, undecodable) ones as
    // MissingTextures says.
    scene::GPUMaterialData material(const scene::MaterialInstance& material) const;
    // One texture field resolved the same way: its bindless slot, `fallback` when
    // absent, the checker for a failed colour texture when MissingTextures says so.
    std::uint32_t field_slot(const scene::TextureSlot& slot, scene::TextureRole role,
                             std::uint32_t fallback) const;
    // Bindless slot of glTF texture `texture` read in `role`, or kTextureSentinel.
    std::uint32_t slot(std::int32_t texture, scene::TextureRole role) const;

    std::uint64_t gpu_bytes() const { return bytes_; } // device memory of all images
    std::size_t image_count() const;
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    void upload(const scene::Scene& scene);
    void release();

    gpu::ResourceManager& resources_;
    gpu::BindlessTable& table_;
    std::shared_ptr<const tex::PreparedTextureSet> prepared_;
    MissingTextures missing_;
    std::vector<GpuTexture> gpu_;
    std::vector<std::uint32_t> slots_; // per record; sentinel where failed
    // Textures sharing an image with another texture but not its sampler get a slot
    // of their own (same view): (glTF texture, role) -> slot.
    std::map<std::pair<std::int32_t, scene::TextureRole>, std::uint32_t> extra_slots_;
    std::vector<gpu::SamplerHandle> samplers_;
    std::uint64_t bytes_ = 0;
    std::vector<std::string> warnings_;
};

} // namespace sherpa::render
