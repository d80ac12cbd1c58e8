#include "texture_cli.h"

#include <charconv>
#include <cmath>

namespace sherpa::cli {

std::optional<std::filesystem::path> TextureCliOptions::resolved_cache_dir() const {
    if (!use_cache) return std::nullopt;
    return cache_dir ? *cache_dir : tex::default_cache_dir_from_environment();
}

tex::PipelineOptions TextureCliOptions::pipeline_options() const {
    // The options mapped once (gpu_settings()), then as the renderer maps them.
    return render::texture_pipeline_options(gpu_settings());
}

render::TextureSettings TextureCliOptions::gpu_settings() const {
    render::TextureSettings s;
    s.cache_dir = resolved_cache_dir();
    s.cache_cap_bytes = cache_cap_bytes;
    s.quality = quality;
    s.force_rgba8 = no_bc;
    s.decode_bc7_on_cpu = !keep_bc7;
    return s;
}

OptionMatch parse_texture_option(Args args, std::size_t& i, TextureCliOptions& out,
                                 std::string& error) {
    const std::string_view a = args[i];
    auto value = [&]() -> std::optional<std::string_view> {
        if (i + 1 >= args.size()) return std::nullopt;
        return args[++i];
    };
    if (a == "--no-cache") {
        out.use_cache = false;
    } else if (a == "--no-bc") {
        out.no_bc = true;
    } else if (a == "--keep-bc7") {
        out.keep_bc7 = true;
    } else if (a == "--missing-textures") {
        const auto v = value();
        const auto mode = v ? render::parse_missing_textures(*v) : std::nullopt;
        if (!mode) {
            error = "--missing-textures needs checker or neutral";
            return OptionMatch::Bad;
        }
        out.missing = *mode;
    } else if (a == "--cache-dir") {
        const auto v = value();
        if (!v || v->empty()) {
            error = "--cache-dir needs a directory";
            return OptionMatch::Bad;
        }
        out.cache_dir = std::filesystem::path(std::string(*v));
    } else if (a == "--cache-cap-mb") {
        const auto v = value();
        std::uint64_t mb = 0;
        const auto [end, ec] =
            v ? std::from_chars(v->data(), v->data() + v->size(), mb) : std::from_chars_result{};
        if (!v || ec != std::errc() || end != v->data() + v->size() || mb == 0) {
            error = "--cache-cap-mb needs a positive number";
            return OptionMatch::Bad;
        }
        out.cache_cap_bytes = mb << 20;
    } else if (a == "--quality") {
        const auto v = value();
        int level = -1;
        const auto [end, ec] =
            v ? std::from_chars(v->data(), v->data() + v->size(), level) : std::from_chars_result{};
        if (!v || ec != std::errc() || end != v->data() + v->size() || level < tex::kBc7MinLevel ||
            level > tex::kBc7MaxLevel) {
            error = "--quality must be " + std::to_string(tex::kBc7MinLevel) + ".." +
                    std::to_string(tex::kBc7MaxLevel);
            return OptionMatch::Bad;
        }
        out.quality = level;
    } else {
        return OptionMatch::NotMine;
    }
    return OptionMatch::Taken;
}

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
    if (t.failed) {
        j["failed"] = true;
        j["location"] = t.location;
        j["uses"] = t.uses;
    }
    return j;
}

nlohmann::json image_problem_json(const tex::ImageProblem& p) {
    nlohmann::json j = {{"image", p.image},
                        {"state", tex::to_string(p.state)},
                        {"location", p.location},
                        {"uses", p.uses}};
    if (!p.reason.empty()) j["reason"] = p.reason;
    return j;
}

} // namespace sherpa::cli
