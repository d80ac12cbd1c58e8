// sherpa-cli textures SCENE [--cache-dir DIR] [--cache-cap-mb N] [--quality N] [--no-cache]
//                          [--no-bc] [--json]
// Runs the texture pipeline over the displayed scene and prints, per (image,
// role), what the texture-cache dock shows.
#include "cli_common.h"

#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/texture_pipeline.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr const char* kUsage =
    "usage: sherpa-cli textures SCENE [--cache-dir DIR] [--cache-cap-mb N] [--quality N] "
    "[--no-cache] [--no-bc] [--json]\n"
    "  --cache-cap-mb N   least recently used files go beyond N MiB (default 2048)\n"
    "  --quality N   BC7 quality level 0 (fastest) .. 4 (best); default 1\n"
    "  --no-bc       pretend the device cannot sample BC formats (RGBA8 fallback)\n";

nlohmann::json texture_json(const tex::PreparedTexture& t) {
    nlohmann::json j = {
        {"image", t.image},
        {"source", t.source},
        {"role", tex::role_name(t.role)},
        {"format", tex::vk_format_name(t.format)},
        {"width", t.width},
        {"height", t.height},
        {"mips", t.levels.size()},
        {"state", tex::to_string(t.state)},
        {"cache_file", t.cache_file.empty()
                           ? nlohmann::json(nullptr)
                           : nlohmann::json(std::filesystem::absolute(t.cache_file).string())},
        {"hash", t.source_hash.hex()},
        {"textures", t.textures},
        {"bytes_on_disk", t.bytes_on_disk},
        {"bytes_gpu", t.bytes_gpu},
        {"decode_ms", t.decode_ms},
        {"mip_ms", t.mip_ms},
        {"encode_ms", t.encode_ms},
        {"psnr",
         t.psnr && std::isfinite(*t.psnr) ? nlohmann::json(*t.psnr) : nlohmann::json(nullptr)},
    };
    if (!t.note.empty()) j["note"] = t.note;
    if (t.failed) j["failed"] = true;
    return j;
}

} // namespace

int run_textures(Args args) {
    std::string_view spec;
    bool as_json = false, use_cache = true;
    tex::PipelineOptions options;
    std::optional<std::filesystem::path> cache_dir;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        if (a == "--json") {
            as_json = true;
        } else if (a == "--no-cache") {
            use_cache = false;
        } else if (a == "--no-bc") {
            options.device_supports_bc = false;
        } else if (a == "--cache-dir" && i + 1 < args.size()) {
            cache_dir = std::filesystem::path(std::string(args[++i]));
        } else if (a == "--cache-cap-mb" && i + 1 < args.size()) {
            const std::string_view v = args[++i];
            std::uint64_t mb = 0;
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), mb);
            if (ec != std::errc() || end != v.data() + v.size() || mb == 0) {
                std::fprintf(stderr, "error: --cache-cap-mb needs a positive number\n%s", kUsage);
                return kExitUsage;
            }
            options.cache_cap_bytes = mb << 20;
        } else if (a == "--quality" && i + 1 < args.size()) {
            const std::string_view v = args[++i];
            int level = -1;
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), level);
            if (ec != std::errc() || end != v.data() + v.size() || level < tex::kBc7MinLevel ||
                level > tex::kBc7MaxLevel) {
                std::fprintf(stderr, "error: --quality must be %d..%d\n%s", tex::kBc7MinLevel,
                             tex::kBc7MaxLevel, kUsage);
                return kExitUsage;
            }
            options.bc7_level = level;
        } else if (!a.empty() && a[0] != '-' && spec.empty()) {
            spec = a;
        } else {
            std::fprintf(stderr, "error: unexpected argument '%.*s'\n%s",
                         static_cast<int>(a.size()), a.data(), kUsage);
            return kExitUsage;
        }
    }
    if (spec.empty()) {
        std::fprintf(stderr, "%s", kUsage);
        return kExitUsage;
    }
    if (use_cache)
        options.cache_dir = cache_dir ? *cache_dir : tex::default_cache_dir_from_environment();
    const LoadResult r = load_scene(spec);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    const tex::PreparedTextureSet set = tex::prepare_textures(*r.scene, options);
    for (const std::string& w : set.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (as_json) {
        nlohmann::json j = {
            {"cache_dir",
             options.cache_dir
                 ? nlohmann::json(std::filesystem::absolute(*options.cache_dir).string())
                 : nlohmann::json(nullptr)},
            {"quality", options.bc7_level},
            {"simd", tex::to_string(options.simd)},
            {"textures", nlohmann::json::array()},
            {"warnings", set.warnings}};
        for (const auto& t : set.textures) j["textures"].push_back(texture_json(t));
        std::cout << j.dump(1) << "\n";
        return kExitOk;
    }
    std::printf("%5s %-6s %-26s %9s %4s %-12s %8s %8s %7s  %s\n", "image", "role", "format", "size",
                "mips", "state", "dec ms", "enc ms", "psnr", "source");
    for (const auto& t : set.textures) {
        const std::string size = std::to_string(t.width) + "x" + std::to_string(t.height);
        char psnr[16] = "-";
        if (t.psnr && std::isfinite(*t.psnr)) std::snprintf(psnr, sizeof psnr, "%.2f", *t.psnr);
        std::printf("%5d %-6s %-26s %9s %4zu %-12s %8.1f %8.1f %7s  %s\n", t.image,
                    std::string(tex::role_name(t.role)).c_str(),
                    std::string(tex::vk_format_name(t.format)).c_str(), size.c_str(),
                    t.levels.size(), std::string(tex::to_string(t.state)).c_str(), t.decode_ms,
                    t.mip_ms + t.encode_ms, psnr, t.source.c_str());
    }
    return kExitOk;
}

} // namespace sherpa::cli
