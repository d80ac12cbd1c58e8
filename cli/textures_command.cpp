// sherpa-cli textures SCENE [--cache-dir DIR] [--cache-cap-mb N] [--quality N] [--no-cache]
//                          [--no-bc] [--json] [--export-source DIR]
// Runs the texture pipeline over the displayed scene and prints, per (image,
// role), what the texture-cache dock shows. --export-source writes every source
// image as the engine decoded it (level 0 PNG) instead.
#include "cli_common.h"
#include "texture_cli.h"

#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/source_export.h>
#include <sherpa/texture/texture_pipeline.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr std::string_view kUsage = "textures"; // main.cpp's usage text

// Exit 1 when some image could not be exported (each named on stderr).
int export_source_images(const scene::Scene& scene, const std::filesystem::path& dir,
                         bool as_json) {
    const std::vector<tex::SourceExport> exports = tex::export_sources(scene, dir);
    nlohmann::json j = nlohmann::json::array();
    bool failed = false;
    for (const tex::SourceExport& e : exports) {
        failed |= !e.error.empty();
        if (!e.error.empty())
            std::fprintf(stderr, "error: image %d: %s\n", e.image, e.error.c_str());
        if (as_json) {
            j.push_back(
                {{"image", e.image},
                 {"file", e.file.string()},
                 {"width", e.width},
                 {"height", e.height},
                 {"error", e.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.error)}});
        } else if (e.error.empty()) {
            std::printf("%5d %5ux%-5u %s\n", e.image, e.width, e.height, e.file.string().c_str());
        }
    }
    if (as_json) std::cout << nlohmann::json{{"exported", j}}.dump(1) << "\n";
    return failed ? kExitLoadError : kExitOk;
}

} // namespace

int run_textures(Args args) {
    std::string_view spec;
    bool as_json = false;
    std::optional<std::filesystem::path> export_dir;
    TextureCliOptions texture_options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        std::string error;
        const OptionMatch m = parse_texture_option(args, i, texture_options, error);
        if (m == OptionMatch::Bad) return usage_error(error, kUsage);
        if (m == OptionMatch::Taken) continue;
        if (a == "--json") {
            as_json = true;
        } else if (a == "--export-source") {
            if (i + 1 >= args.size())
                return usage_error("--export-source needs a directory", kUsage);
            export_dir = std::filesystem::path(args[++i]);
        } else if (!a.empty() && a[0] != '-' && spec.empty()) {
            spec = a;
        } else {
            return usage_error("unexpected argument '" + std::string(a) + "'", kUsage);
        }
    }
    if (spec.empty()) return usage_error("no SCENE given", kUsage);
    const tex::PipelineOptions options = texture_options.pipeline_options();
    const scene::LoadResult r = scene::load_scene(spec);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    if (export_dir) return export_source_images(*r.scene, *export_dir, as_json);
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
                    t.mip_ms + t.encode_ms, psnr,
                    t.failed ? t.location.c_str() : t.source.c_str()); // failed: the full path
    }
    return kExitOk;
}

} // namespace sherpa::cli
