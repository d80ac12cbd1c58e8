#pragma once
// A scene's textures on the GPU: decoded to RGBA8 (sRGB for colour roles, UNORM
// otherwise) with full mip chains, registered in the bindless table, plus the
// sampler objects the glTF samplers map to. Stands in until the texture pipeline
// (BC7/BC5/KTX2 cache) lands.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <sherpa/gpu/bindless.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/scene/scene.h>

namespace sherpa::gpu {

class SceneTextures {
public:
    SceneTextures(ResourceManager& resources, BindlessTable& table, const Scene& scene);
    ~SceneTextures();
    SceneTextures(const SceneTextures&) = delete;
    SceneTextures& operator=(const SceneTextures&) = delete;

    // Bindless slot of scene texture `texture` read as colour (sRGB) or data, or
    // `fallback` (a default slot) when the slot is absent or could not be decoded.
    std::uint32_t slot(std::int32_t texture, bool srgb, std::uint32_t fallback) const;
    std::uint64_t gpu_bytes() const { return bytes_; }
    std::size_t image_count() const { return images_.size(); }
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    ResourceManager& resources_;
    BindlessTable& table_;
    std::vector<ImageHandle> images_;
    std::vector<SamplerHandle> samplers_;
    std::vector<std::uint32_t> slots_;
    std::map<std::pair<std::int32_t, bool>, std::uint32_t> slot_of_; // (texture, srgb) -> slot
    std::uint64_t bytes_ = 0;
    std::vector<std::string> warnings_;
};

// Decodes PNG/JPEG bytes (or takes generated RGBA8 pixels) into tightly packed
// RGBA8. Returns false with `error` set when the image cannot be decoded.
bool decode_rgba8(const ImageRecord& image, std::vector<std::uint8_t>& rgba, std::uint32_t& width,
                  std::uint32_t& height, std::string& error);

} // namespace sherpa::gpu
