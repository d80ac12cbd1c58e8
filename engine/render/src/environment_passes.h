#pragma once
// The compute passes that turn an equirectangular environment into what shading reads
// (shaders/ibl_*.comp), one class per pass, all over one descriptor layout: binding 0
// the source (sampler), binding 1 the destination level (storage image array, one
// layer per cube face). EnvironmentMap (environment_map.h) orders them.
#include <cstddef>
#include <cstdint>
#include <span>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/unique_handle.h>

namespace sherpa::render {

// C++ twin of IblPush (shaders/include/ibl_sampling.glsl).
struct GPUIblPush {
    std::uint32_t face_size = 0;
    std::uint32_t source_lod = 0;
    float roughness = 0.0f;
    std::uint32_t samples = 0;
    float source_size = 0.0f;
    float source_levels = 0.0f;
    float equirect_lod = 0.0f;
    std::uint32_t pad = 0;
};
static_assert(sizeof(GPUIblPush) == 32);
static_assert(offsetof(GPUIblPush, roughness) == 8);
static_assert(offsetof(GPUIblPush, equirect_lod) == 24);

// The descriptor layout, pipeline layout and a pool for the sets of one build.
class IblLayout {
public:
    IblLayout(VkDevice device, std::uint32_t max_sets);
    // A set reading `source` (may be null: the LUT pass) and writing `destination`.
    VkDescriptorSet bind(VkSampler sampler, VkImageView source, VkImageView destination);
    VkPipelineLayout layout() const { return layout_.get(); }

private:
    VkDevice device_;
    gpu::UniqueDescriptorSetLayout set_layout_;
    gpu::UniquePipelineLayout layout_;
    gpu::UniqueDescriptorPool pool_;
};

// Records one dispatch over face_size^2 x `layers` texels.
class IblComputePass {
protected:
    IblComputePass(VkDevice device, VkPipelineLayout layout, std::span<const std::uint32_t> code,
                   const char* what, const VkSpecializationInfo* constants = nullptr);
    void dispatch(VkCommandBuffer cmd, VkDescriptorSet set, const GPUIblPush& push,
                  std::uint32_t layers) const;

private:
    VkPipelineLayout layout_;
    gpu::UniquePipeline pipeline_;
};

// Equirectangular image -> level 0 of the radiance cube.
class EquirectToCubePass : IblComputePass {
public:
    EquirectToCubePass(VkDevice device, VkPipelineLayout layout);
    void record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t face_size,
                float equirect_lod) const;
};

// Level n + 1 of the radiance cube from level n (2x2 box).
class CubeDownsamplePass : IblComputePass {
public:
    CubeDownsamplePass(VkDevice device, VkPipelineLayout layout);
    void record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t face_size,
                std::uint32_t source_lod) const;
};

// One level of a cube prefiltered for a lobe: GGX specular, Lambert irradiance or
// Charlie sheen (filtered importance sampling of the radiance cube).
class PrefilterPass : IblComputePass {
public:
    enum class Lobe : std::uint32_t { Ggx = 0, Lambert = 1, Charlie = 2 }; // IBL_* in GLSL
    PrefilterPass(VkDevice device, VkPipelineLayout layout, Lobe lobe);
    void record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t face_size, float roughness,
                std::uint32_t samples, std::uint32_t source_size,
                std::uint32_t source_levels) const;
};

// The split-sum lookup table: GGX scale and bias, Charlie albedo (ibl_lut.comp); or,
// `anisotropic`, the anisotropic GGX's scale and bias (ibl_lut_anisotropic.comp).
class BrdfLutPass : IblComputePass {
public:
    BrdfLutPass(VkDevice device, VkPipelineLayout layout, bool anisotropic = false);
    // `size` texels of n.v (and of roughness for the isotropic table) in each of `layers`.
    void record(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t size, std::uint32_t samples,
                std::uint32_t layers = 1) const;
};

// A storage view of one level (layers 0 .. layers - 1) of an RGBA16F `image`, as the
// passes write it (image2DArray).
gpu::UniqueImageView level_view(VkDevice device, VkImage image, std::uint32_t level,
                                std::uint32_t layers);

} // namespace sherpa::render
