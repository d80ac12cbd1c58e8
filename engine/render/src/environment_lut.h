#pragma once
// The split-sum lookup table (shaders/ibl_lut.comp): GGX scale and bias on F0 and the
// Charlie directional albedo over (n.v, roughness). It is a constant of the BRDF, not of
// the environment, so it is made once and shared by every environment that follows
// (SceneState keeps it while an environment is set and frees it with the last one:
// without an environment nothing of it stays on the GPU).
// The anisotropic table (ibl_lut_anisotropic.comp) is KHR_materials_anisotropy's: the
// anisotropic GGX's scale and bias over (n.v, roughness, strength, the view's azimuth
// from the direction); SceneState makes it only while an environment and a scene with
// an anisotropic material are both loaded.
#include <sherpa/gpu/resources.h>

namespace sherpa::render {

class BrdfLut {
public:
    static constexpr std::uint32_t kSize = 64, kSamples = 128;
    // The anisotropic table: n.v x roughness texels, strength x azimuth layers (the
    // shader's constants, ibl_lut_anisotropic.comp).
    static constexpr std::uint32_t kAnisotropicNDotV = 32, kAnisotropicRoughness = 16,
                                   kAnisotropicLayers = 8 * 6, kAnisotropicSamples = 256;

    // Builds the table (the isotropic one, or the anisotropic) on the GPU and waits.
    BrdfLut(gpu::Context& context, gpu::ResourceManager& resources, bool anisotropic = false);
    ~BrdfLut();
    BrdfLut(const BrdfLut&) = delete;
    BrdfLut& operator=(const BrdfLut&) = delete;

    // In SHADER_READ_ONLY_OPTIMAL; RGBA16F, kSize x kSize (the anisotropic: a 2D array).
    VkImageView view() const;
    std::uint64_t bytes() const {
        return anisotropic_ ? std::uint64_t{kAnisotropicNDotV} * kAnisotropicRoughness *
                                  kAnisotropicLayers * 8
                            : std::uint64_t{kSize} * kSize * 8;
    }
    double build_ms() const { return build_ms_; }         // wall clock, recording to done
    double build_gpu_ms() const { return build_gpu_ms_; } // the pass, by GPU timestamps

private:
    gpu::ResourceManager& resources_;
    gpu::ImageHandle image_;
    bool anisotropic_;
    double build_ms_ = 0.0, build_gpu_ms_ = 0.0;
};

} // namespace sherpa::render
