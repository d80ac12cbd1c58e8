#pragma once
// The split-sum lookup table (shaders/ibl_lut.comp): GGX scale and bias on F0 and the
// Charlie directional albedo over (n.v, roughness). It is a constant of the BRDF, not of
// the environment, so it is made once and shared by every environment that follows
// (SceneState keeps it while an environment is set and frees it with the last one:
// without an environment nothing of it stays on the GPU).
#include <sherpa/gpu/resources.h>

namespace sherpa::render {

class BrdfLut {
public:
    static constexpr std::uint32_t kSize = 64, kSamples = 128;

    // Builds the table on the GPU and waits for it.
    BrdfLut(gpu::Context& context, gpu::ResourceManager& resources);
    ~BrdfLut();
    BrdfLut(const BrdfLut&) = delete;
    BrdfLut& operator=(const BrdfLut&) = delete;

    // In SHADER_READ_ONLY_OPTIMAL; RGBA16F, kSize x kSize.
    VkImageView view() const;
    std::uint64_t bytes() const { return std::uint64_t{kSize} * kSize * 8; }
    double build_ms() const { return build_ms_; }         // wall clock, recording to done
    double build_gpu_ms() const { return build_gpu_ms_; } // the pass, by GPU timestamps

private:
    gpu::ResourceManager& resources_;
    gpu::ImageHandle image_;
    double build_ms_ = 0.0, build_gpu_ms_ = 0.0;
};

} // namespace sherpa::render
