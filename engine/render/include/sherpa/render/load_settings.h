#pragma once
// How Renderer::load() brings a scene to the GPU: the vertex streams it uploads, how
// missing textures are drawn (both chosen per load: SceneSetup, scene_setup.h) and how
// a renderer prepares textures itself (TextureSettings). No Vulkan types.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

#include <sherpa/core/progress.h>
#include <sherpa/texture/texture_pipeline.h>

namespace sherpa::render {

enum class StreamPolicy {
    UsedByMaterials, // the default: what shading reads
    AllPresent,      // every authored or generated stream (debug views of unused streams)
};

// How material slots whose texture is missing or undecodable are drawn.
enum class MissingTextures : std::uint8_t {
    // A magenta/black checker in colour slots (base colour, emissive), the flat
    // normal in normal slots, neutral data (occlusion 1, metallic-roughness factors
    // alone) elsewhere: as a debug view would, so the failure is visible.
    Checker,
    // The glTF defaults for an absent texture in every slot (white colour).
    Neutral,
};
std::string_view to_string(MissingTextures m); // "checker", "neutral"
std::optional<MissingTextures> parse_missing_textures(std::string_view name);

// How textures are prepared for a device (texture_target(), texture_pipeline_options()
// of scene_textures.h), and how a renderer prepares them when it is handed a bare Scene.
struct TextureSettings {
    std::optional<std::filesystem::path> cache_dir; // nullopt: no disk cache
    std::uint64_t cache_cap_bytes = tex::kDefaultCacheCapBytes;
    int quality = tex::kBc7DefaultLevel; // BC7 level
    // Upload RGBA8 even where the device samples BC (what devices without BC get).
    bool force_rgba8 = false;
    // CPU devices (lavapipe) decode a whole BC7 block for every texel they fetch:
    // measured 5-7x the frame time of RGBA8 for DamagedHelmet at 720p. There the
    // cached BC7 blocks are decoded to RGBA8 at upload (same pixels as sampling the
    // blocks, 4x the memory); false keeps the blocks. BC5 costs the same either way
    // and stays compressed.
    bool decode_bc7_on_cpu = true;
    // Handed to the texture pipeline (tex::PipelineOptions): textures ready of
    // textures, and a token that stops the preparation (the set comes back
    // `cancelled` and empty).
    core::ProgressCallback progress;
    const core::CancelToken* cancel = nullptr;
};

} // namespace sherpa::render
