#pragma once
// Texture-cache options shared by `sherpa-cli textures` and `sherpa-cli render`
// (one parser, one usage text) and the JSON record of one prepared texture.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include <sherpa/render/scene_textures.h>
#include <sherpa/texture/texture_pipeline.h>

#include "cli_common.h"

namespace sherpa::cli {

inline constexpr const char* kTextureOptionsSynopsis =
    "[--cache-dir DIR] [--cache-cap-mb N] [--quality N] [--no-cache] [--no-bc]\n"
    "    [--keep-bc7] [--missing-textures checker|neutral]";
inline constexpr const char* kTextureOptionsHelp =
    "  --cache-dir DIR    texture cache (default $XDG_CACHE_HOME/sherpa/textures, else\n"
    "                     ~/.cache/sherpa/textures)\n"
    "  --cache-cap-mb N   least recently used files go beyond N MiB (default 2048)\n"
    "  --no-cache         neither read nor write the cache\n"
    "  --quality N        BC7 quality level 0 (fastest) .. 4 (best); default 1\n"
    "  --no-bc            upload RGBA8 as if the device could not sample BC formats\n"
    "  --keep-bc7         sample BC7 blocks on CPU devices too (by default they are\n"
    "                     decoded to RGBA8 at upload there: sampling BC7 is slow)\n"
    "  --missing-textures checker|neutral\n"
    "                     render only: draw material slots whose image is missing or\n"
    "                     undecodable as a magenta/black checker in colour slots\n"
    "                     (default), or as the glTF defaults (white, flat normal)\n";

struct TextureCliOptions {
    bool use_cache = true;
    std::optional<std::filesystem::path> cache_dir; // --cache-dir; else the default
    std::uint64_t cache_cap_bytes = tex::kDefaultCacheCapBytes;
    int quality = tex::kBc7DefaultLevel;
    bool no_bc = false;
    bool keep_bc7 = false; // render only: no BC7 decoding at upload on CPU devices
    render::MissingTextures missing = render::MissingTextures::Checker; // render only

    // The directory in use: nullopt with --no-cache, else --cache-dir or the default.
    std::optional<std::filesystem::path> resolved_cache_dir() const;
    // The one mapping of these options: for a renderer (which prepares textures for
    // its device's render::texture_target()) and for the texture pipeline run directly.
    render::TextureSettings gpu_settings() const;
    // gpu_settings() as the texture pipeline's options (BC unless --no-bc).
    tex::PipelineOptions pipeline_options() const;
};

enum class OptionMatch { NotMine, Taken, Bad };

// If args[i] is a texture option, consumes it (and its value, advancing i) into
// `out`; Bad sets `error` to what is wrong with it.
OptionMatch parse_texture_option(Args args, std::size_t& i, TextureCliOptions& out,
                                 std::string& error);

// One prepared texture as `textures --json` and `render --report` print it.
nlohmann::json texture_json(const tex::PreparedTexture& t);
// An image that cannot become a texture, as `info --json` prints it.
nlohmann::json image_problem_json(const tex::ImageProblem& p);

} // namespace sherpa::cli
