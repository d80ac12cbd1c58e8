#pragma once
// An environment on the GPU: made once from an equirectangular image by the compute
// passes of environment_passes.h, then read by every lit frame (shaders/include/ibl.glsl,
// set 1 bindings 4-7) and the background pass. Only what shading reads is kept: the
// GGX-prefiltered specular cube (its level 0 is the sharp environment), the irradiance
// cube (unless the irradiance is SH9) and the Charlie (sheen) cube; the source image and
// the radiance cube the prefilters sample are freed after the build. The split-sum
// lookup table is not the environment's: it is shared (environment_lut.h).
#include <optional>

#include "environment_lut.h"

#include <sherpa/gpu/resources.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/environment_sh.h>

namespace sherpa::render {

class EnvironmentMap {
public:
    // Sizes of what is made (the specular cube's face follows the source: a quarter of
    // its width as a power of two, within these bounds).
    static constexpr std::uint32_t kMinCube = 16, kMaxCube = 512, kLowestLevel = 8;
    static constexpr std::uint32_t kIrradianceSize = 32, kSheenSize = 64;
    // Samples per texel. Filtered importance sampling reads coarser source levels for
    // wider lobes, so few samples suffice; the sharpest prefiltered level (the largest,
    // and the narrowest lobe) takes the fewest.
    static constexpr std::uint32_t kSpecularSamplesFirst = 16, kSpecularSamples = 32,
                                   kIrradianceSamples = 48, kSheenSamples = 32;

    // Builds everything on the GPU and waits for it. `image` must be valid(); `lut`
    // outlives the map (its bytes are counted in stats(), and its build time where
    // `lut_built` says it was made for this environment).
    EnvironmentMap(gpu::Context& context, gpu::ResourceManager& resources,
                   const EnvironmentImage& image, const EnvironmentOptions& options,
                   const BrdfLut& lut, bool lut_built);
    ~EnvironmentMap();
    EnvironmentMap(const EnvironmentMap&) = delete;
    EnvironmentMap& operator=(const EnvironmentMap&) = delete;

    // Bindings 4 (specular), 5 (irradiance; the specular cube, never read, where the
    // irradiance is SH9), 6 (LUT), 7 (sheen) of a frame set, and 10 the anisotropic
    // LUT where there is one (null: binding 10 left as it was, never read).
    void write_descriptors(VkDevice device, VkDescriptorSet set,
                           const BrdfLut* anisotropic_lut) const;
    const EnvironmentStats& stats() const { return stats_; }
    // The specular cube with its sampler (level 0 is the sharp environment): the path
    // tracer's radiance.
    VkDescriptorImageInfo specular_descriptor() const;
    // IrradianceMode::Sh9: the coefficients of irradiance / pi (irradiance_sh9()).
    const std::optional<Sh9>& irradiance_sh() const { return irradiance_sh_; }

private:
    gpu::ResourceManager& resources_;
    const BrdfLut& lut_;
    gpu::ImageHandle specular_, irradiance_, sheen_;
    gpu::SamplerHandle sampler_;
    EnvironmentStats stats_;
    std::optional<Sh9> irradiance_sh_;
};

} // namespace sherpa::render
