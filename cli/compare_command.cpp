// sherpa-cli compare A B [--json] [--image OUT.png]
// Structural diff of two glTF files (engine/lab/compare.h), their JSON diffed by
// pointer (engine/lab/json_diff.h) and, with --image, a rendered difference of both
// from the same camera (A framed): the heat over a dimmed side A, both sides, and
// the legend with its numbers drawn in.
#include "cli_common.h"
#include "environment_options.h"

#include <sherpa/lab/compare.h>
#include <sherpa/lab/family.h>
#include <sherpa/lab/json_diff.h>
#include <sherpa/scene/scene_loader.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr std::string_view kUsage = "compare"; // main.cpp's usage text

nlohmann::json optional(const std::optional<double>& v) {
    return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json comparison_json(const lab::FileComparison& c) {
    nlohmann::json counts = nlohmann::json::object(), prims = nlohmann::json::array(),
                   materials = nlohmann::json::array(), textures = nlohmann::json::array();
    for (const lab::CountDiff& d : c.counts) counts[d.name] = {{"a", d.a}, {"b", d.b}};
    for (const lab::PrimitiveDiff& p : c.primitives)
        prims.push_back(
            {{"mesh", p.mesh},
             {"primitive", p.primitive},
             {"vertices", {p.vertices_a, p.vertices_b}},
             {"indices", {p.indices_a, p.indices_b}},
             {"position_error", {{"max", p.position_max}, {"rms", p.position_rms}}},
             {"normal_error_deg", {{"max", p.normal_max_deg}, {"mean", p.normal_mean_deg}}},
             {"tangent_error_deg",
              {{"max", optional(p.tangent_max_deg)}, {"mean", optional(p.tangent_mean_deg)}}},
             {"uv_error", {{"max", p.uv_max}, {"rms", p.uv_rms}}},
             {"note", p.note}});
    for (const lab::MaterialDiff& m : c.materials)
        materials.push_back({{"material", m.material}, {"fields", m.fields}});
    for (const lab::TextureDiff& t : c.textures)
        textures.push_back({{"image", t.image},
                            {"a", t.a},
                            {"b", t.b},
                            {"size_a", {t.width_a, t.height_a}},
                            {"size_b", {t.width_b, t.height_b}},
                            {"bytes", {t.bytes_a, t.bytes_b}},
                            {"psnr_db", optional(t.psnr)},
                            {"identical", t.psnr && std::isinf(*t.psnr)},
                            {"note", t.note}});
    return {{"counts", counts},
            {"primitives", prims},
            {"materials", materials},
            {"textures", textures},
            {"bytes",
             {{"file", {c.file_bytes_a, c.file_bytes_b}},
              {"total", {c.total_bytes_a, c.total_bytes_b}},
              {"images", {c.image_bytes_a, c.image_bytes_b}}}},
            {"notes", c.notes}};
}

// Both files' JSON, diffed by pointer; an error (a built-in scene) says why not.
lab::JsonDiff diff_files(const std::string& a, const std::string& b) {
    std::string text_a, text_b, error;
    if (!lab::read_gltf_json(a, text_a, error) || !lab::read_gltf_json(b, text_b, error)) {
        lab::JsonDiff d;
        d.error = error;
        return d;
    }
    return lab::json_diff(text_a, text_b);
}

nlohmann::json json_diff_json(const lab::JsonDiff& d) {
    if (!d.error.empty()) return {{"error", d.error}};
    nlohmann::json added = nlohmann::json::array(), removed = nlohmann::json::array(),
                   changed = nlohmann::json::array(), drift = nlohmann::json::array();
    for (const lab::JsonChange& c : d.changes) {
        if (c.kind == lab::JsonChangeKind::Added)
            added.push_back(c.pointer);
        else if (c.kind == lab::JsonChangeKind::Removed)
            removed.push_back(c.pointer);
        else
            changed.push_back(
                {{"pointer", c.pointer}, {"fields", c.fields}, {"field_count", c.field_count}});
    }
    for (const lab::AccessorDrift& a : d.drift)
        drift.push_back(
            {{"use", a.use},
             {"accessor", {a.accessor_a, a.accessor_b}},
             {"min", {a.min_a, a.min_b}},
             {"max", {a.max_a, a.max_b}},
             {"comparable", a.comparable},
             {"drift", a.comparable ? nlohmann::json(a.drift) : nlohmann::json(nullptr)},
             {"relative", a.comparable ? nlohmann::json(a.relative) : nlohmann::json(nullptr)},
             {"note", a.note}});
    return {{"objects", {{"a", d.objects_a}, {"b", d.objects_b}, {"unchanged", d.unchanged}}},
            {"added", added},
            {"removed", removed},
            {"changed", changed},
            {"accessor_drift", drift}};
}

void print_json_diff(const lab::JsonDiff& d) {
    if (!d.error.empty()) {
        std::printf("json_diff: not available (%s)\n", d.error.c_str());
        return;
    }
    std::size_t counts[3] = {0, 0, 0};
    for (const lab::JsonChange& c : d.changes) ++counts[static_cast<int>(c.kind)];
    std::printf("json_diff: %zu added, %zu removed, %zu changed, %llu unchanged (objects %llu -> "
                "%llu)\n",
                counts[0], counts[1], counts[2], (unsigned long long)d.unchanged,
                (unsigned long long)d.objects_a, (unsigned long long)d.objects_b);
    constexpr std::size_t kShown = 40; // --json lists every one
    for (std::size_t i = 0; i < d.changes.size() && i < kShown; ++i) {
        const lab::JsonChange& c = d.changes[i];
        std::printf("  %-8s %s\n", std::string(lab::to_string(c.kind)).c_str(), c.pointer.c_str());
        for (const std::string& f : c.fields) std::printf("             %s\n", f.c_str());
        if (c.field_count > c.fields.size())
            std::printf("             ... %zu more fields\n", c.field_count - c.fields.size());
    }
    if (d.changes.size() > kShown)
        std::printf("  ... %zu more objects (--json lists them all)\n", d.changes.size() - kShown);
    for (const lab::AccessorDrift& a : d.drift) {
        std::printf("  min/max  %s (accessor %lld -> %lld): ", a.use.c_str(),
                    (long long)a.accessor_a, (long long)a.accessor_b);
        if (a.comparable)
            std::printf("drift %.6g (%.3g%% of the extent)", a.drift, 100.0 * a.relative);
        else
            std::printf("not comparable");
        std::printf("%s%s\n", a.note.empty() ? "" : "; ", a.note.c_str());
    }
}

void print_text(const lab::FileComparison& c) {
    for (const lab::CountDiff& d : c.counts)
        std::printf("%-11s %10llu %10llu%s\n", d.name.c_str(), (unsigned long long)d.a,
                    (unsigned long long)d.b, d.a != d.b ? "  differs" : "");
    std::printf("bytes: file %llu -> %llu, with external files %llu -> %llu, images %llu -> %llu\n",
                (unsigned long long)c.file_bytes_a, (unsigned long long)c.file_bytes_b,
                (unsigned long long)c.total_bytes_a, (unsigned long long)c.total_bytes_b,
                (unsigned long long)c.image_bytes_a, (unsigned long long)c.image_bytes_b);
    for (const lab::PrimitiveDiff& p : c.primitives) {
        std::printf("mesh %u prim %u: vertices %llu/%llu indices %llu/%llu", p.mesh, p.primitive,
                    (unsigned long long)p.vertices_a, (unsigned long long)p.vertices_b,
                    (unsigned long long)p.indices_a, (unsigned long long)p.indices_b);
        if (!p.note.empty()) {
            std::printf("  %s\n", p.note.c_str());
            continue;
        }
        std::printf("  position max %.4g rms %.4g  normal max %.3g deg  uv max %.4g",
                    p.position_max, p.position_rms, p.normal_max_deg, p.uv_max);
        if (p.tangent_max_deg) std::printf("  tangent max %.3g deg", *p.tangent_max_deg);
        std::printf("\n");
    }
    for (const lab::MaterialDiff& m : c.materials)
        for (const std::string& f : m.fields)
            std::printf("material %u %s\n", m.material, f.c_str());
    for (const lab::TextureDiff& t : c.textures) {
        if (t.psnr)
            std::printf("image %d: PSNR %.2f dB\n", t.image, *t.psnr);
        else
            std::printf("image %d: %s\n", t.image, t.note.c_str());
    }
    for (const std::string& n : c.notes) std::printf("note: %s\n", n.c_str());
}

// The picture's labels: the two files, and under the legend what differs in the
// materials and images (both sides of each field), as stdout lists them.
lab::DifferenceOptions difference_options(const lab::FileComparison& c, const std::string& a,
                                          const std::string& b) {
    lab::DifferenceOptions o;
    o.label_a = "A: " + std::filesystem::path(a).filename().string();
    o.label_b = "B: " + std::filesystem::path(b).filename().string();
    std::vector<std::string> lines;
    for (const lab::MaterialDiff& m : c.materials)
        for (const std::string& f : m.fields)
            lines.push_back("material " + std::to_string(m.material) + " " + f);
    for (const lab::TextureDiff& t : c.textures)
        if (!t.psnr || !std::isinf(*t.psnr)) {
            char psnr[32] = "";
            if (t.psnr) std::snprintf(psnr, sizeof psnr, "PSNR %.2f dB", *t.psnr);
            lines.push_back("image " + std::to_string(t.image) + ": " + (t.psnr ? psnr : t.note));
        }
    constexpr std::size_t kShown = 8; // stdout and --json list every one
    for (std::size_t i = 0; i < lines.size() && i < kShown; ++i) o.captions.push_back(lines[i]);
    if (lines.size() > kShown)
        o.captions.push_back("... " + std::to_string(lines.size() - kShown) + " more (see stdout)");
    return o;
}

} // namespace

int run_compare(Args args) {
    std::vector<std::string> files;
    std::string image;
    bool json = false;
    render::EnvironmentChoice environment; // --image: both lit as render lights its frame
    render::FrameRequest lighting;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string option_error;
        const OptionMatch em =
            parse_environment_option(args, i, lighting, environment, option_error);
        if (em == OptionMatch::Bad) return usage_error(option_error, kUsage);
        if (em == OptionMatch::Taken) continue;
        if (args[i] == "--json")
            json = true;
        else if (args[i] == "--image" && i + 1 < args.size())
            image = std::string(args[++i]);
        else if (!args[i].empty() && args[i][0] != '-')
            files.emplace_back(args[i]);
        else
            return usage_error("unexpected argument '" + std::string(args[i]) + "'", kUsage);
    }
    if (files.size() != 2) return usage_error("give two files", kUsage);
    scene::LoadResult a = scene::load_scene(files[0], lab::lab_load_options());
    scene::LoadResult b =
        a ? scene::load_scene(files[1], lab::lab_load_options()) : scene::LoadResult{};
    if (!a || !b) {
        std::fprintf(stderr, "error: %s\n", (a ? b : a).error.c_str());
        return kExitLoadError;
    }
    const lab::FileComparison c = lab::compare_files(*a.scene, *b.scene);
    const lab::JsonDiff diff = diff_files(files[0], files[1]);
    nlohmann::json out = comparison_json(c);
    out["json_diff"] = json_diff_json(diff);
    if (!image.empty()) {
        lab::DifferenceOptions options = difference_options(c, files[0], files[1]);
        options.lighting = {make_environment_image(environment), lighting};
        const lab::DifferenceImage d = lab::render_difference(*a.scene, *b.scene, options);
        std::string error = d.error;
        if (error.empty() &&
            !tex::write_png(image, d.image.width, d.image.height, d.image.pixels, error))
            error = image + ": " + error;
        if (!error.empty()) {
            std::fprintf(stderr, "error: %s\n", error.c_str());
            return kExitLoadError;
        }
        out["image"] = {
            {"path", image},
            {"mean", d.mean},
            {"max", d.max},
            {"psnr_db", std::isfinite(d.psnr) ? nlohmann::json(d.psnr) : nlohmann::json(nullptr)},
            {"threshold", d.threshold},
            {"over_threshold_percent", d.over_threshold_percent},
            {"scale", d.scale},
            {"size", {d.image.width, d.image.height}},
            {"legend_top", d.legend_top}};
        if (!json)
            std::printf(
                "image %s: mean %.3g max %.0f (white: %.0f) PSNR %.2f dB, %.2f%% pixels over %u\n",
                image.c_str(), d.mean, d.max, d.scale, d.psnr, d.over_threshold_percent,
                d.threshold);
    }
    if (json)
        std::cout << out.dump(2) << "\n";
    else {
        print_text(c);
        print_json_diff(diff);
    }
    return kExitOk;
}

} // namespace sherpa::cli
