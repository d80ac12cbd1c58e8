#pragma once
// Descriptor set 0 of every pipeline: a bindless array of combined image samplers. Slots are handed
// out and given back by scenes; the default textures own slots 0..3 for the whole lifetime of the
// table.
#include <cstdint>
#include <vector>

#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

// Bindless slots registered before any scene texture.
inline constexpr std::uint32_t kWhiteTexture = 0;
inline constexpr std::uint32_t kFlatNormalTexture = 1;
inline constexpr std::uint32_t kBlackTexture = 2;
// Magenta/black 8x8 checker drawn in colour slots whose texture is missing or
// undecodable, so nobody mistakes the failure for intended white.
inline constexpr std::uint32_t kCheckerTexture = 3;
inline constexpr std::uint32_t kDefaultTextureCount = 4;
inline constexpr std::uint32_t kCheckerTextureSize = 8;

class BindlessTable {
public:
    static constexpr std::uint32_t kCapacity = 4096;

    explicit BindlessTable(ResourceManager& resources);
    ~BindlessTable();
    BindlessTable(const BindlessTable&) = delete;
    BindlessTable& operator=(const BindlessTable&) = delete;

    VkDescriptorSetLayout layout() const { return layout_.get(); }
    VkDescriptorSet set() const { return set_; }

    // The image must be in SHADER_READ_ONLY_OPTIMAL whenever a draw may sample it.
    std::uint32_t add(VkImageView view, VkSampler sampler);
    void remove(std::uint32_t slot);

private:
    void write(std::uint32_t binding, std::uint32_t slot, VkImageView view, VkSampler sampler,
               VkImageLayout layout);
    void create_defaults();

    ResourceManager& resources_;
    UniqueDescriptorSetLayout layout_;
    UniqueDescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::uint32_t next_ = 0;
    std::vector<std::uint32_t> free_;
    ImageHandle defaults_[kDefaultTextureCount];
    SamplerHandle default_sampler_;
};

} // namespace sherpa::gpu
