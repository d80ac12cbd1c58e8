// Texture preparation for a target device (texture_target.h): the pipeline, what the
// set says about the device's formats, and BC7 decoded for CPU devices.
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/ktx2.h>
#include <sherpa/texture/texture_target.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace sherpa::tex {

namespace {

// Replaces t's BC7 levels by their RGBA8 decoding (what sampling the blocks returns).
void decode_bc7_levels(PreparedTexture& t) {
    const auto t0 = std::chrono::steady_clock::now();
    const bool srgb = t.format == VkFormat::Bc7SrgbBlock;
    std::uint64_t bytes = 0;
    for (std::size_t l = 0; l < t.levels.size(); ++l) {
        const auto level = static_cast<std::uint32_t>(l);
        t.levels[l] = decode_image(BlockFormat::Bc7, t.levels[l], mip_extent(t.width, level),
                                   mip_extent(t.height, level));
        bytes += t.levels[l].size();
    }
    t.format = srgb ? VkFormat::R8G8B8A8Srgb : VkFormat::R8G8B8A8Unorm;
    t.bytes_gpu = bytes;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    char note[96];
    std::snprintf(note, sizeof note, "BC7 blocks decoded to RGBA8 for the CPU device (%.1f ms)",
                  ms);
    t.note = t.note.empty() ? note : t.note + "; " + note;
}

} // namespace

std::shared_ptr<const PreparedTextureSet> prepare_scene_textures(const scene::Scene& scene,
                                                                 const TextureTarget& target,
                                                                 PipelineOptions options) {
    const bool forced_rgba8 = !options.device_supports_bc;
    options.device_supports_bc = target.bc && !forced_rgba8;
    auto set = std::make_shared<PreparedTextureSet>(prepare_textures(scene, options));
    // Say why there is no BC: the device (a warning: textures cost 4x the memory and
    // no setting helps), or the settings (a notice: the user asked for it).
    if (!set->textures.empty() && !options.device_supports_bc) {
        std::erase_if(set->warnings, [](const std::string& w) {
            return w.starts_with("device cannot sample BC formats");
        });
        if (!target.bc)
            set->warnings.insert(set->warnings.begin(),
                                 target.name +
                                     " cannot sample BC7/BC5 (textureCompressionBC or format "
                                     "features missing): textures fall back to uncompressed RGBA8");
        else
            set->notices.push_back("RGBA8 forced (--no-bc): textures are uploaded uncompressed "
                                   "although " +
                                   target.name + " samples BC7/BC5");
    }
    if (target.cpu_decode) {
        // One texture at a time: decode_image spreads its block rows over the cores.
        std::size_t bc7 = 0;
        for (PreparedTexture& t : set->textures)
            if (!t.failed &&
                (t.format == VkFormat::Bc7SrgbBlock || t.format == VkFormat::Bc7UnormBlock)) {
                decode_bc7_levels(t);
                ++bc7;
            }
        // Nothing for the user to act on: the pixels are the same. A notice, not a warning.
        if (bc7 > 0)
            set->notices.push_back(
                std::to_string(bc7) + " BC7 texture(s) decoded to RGBA8 at upload: " + target.name +
                " is a CPU device, where sampling BC7 costs several times RGBA8");
    }
    return set;
}

} // namespace sherpa::tex
