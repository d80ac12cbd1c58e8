// sherpa-cli compare A B [--json] [--image OUT.png]
// Structural diff of two glTF files (engine/lab/compare.h) and, with --image, a
// rendered difference heat map of both from the same camera (A framed).
#include "cli_common.h"

#include <sherpa/lab/compare.h>
#include <sherpa/lab/family.h>
#include <sherpa/scene/scene_loader.h>

#include <cmath>
#include <cstdio>
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

} // namespace

int run_compare(Args args) {
    std::vector<std::string> files;
    std::string image;
    bool json = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
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
    LoadResult a = load_scene(files[0], lab::lab_load_options());
    LoadResult b = a ? load_scene(files[1], lab::lab_load_options()) : LoadResult{};
    if (!a || !b) {
        std::fprintf(stderr, "error: %s\n", (a ? b : a).error.c_str());
        return kExitLoadError;
    }
    const lab::FileComparison c = lab::compare_files(*a.scene, *b.scene);
    nlohmann::json out = comparison_json(c);
    if (!image.empty()) {
        const lab::DifferenceImage d = lab::render_difference(*a.scene, *b.scene, {});
        std::string error = d.error;
        if (error.empty() &&
            !tex::write_png(image, d.heat.width, d.heat.height, d.heat.pixels, error))
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
            {"over_threshold_percent", d.over_threshold_percent}};
        if (!json)
            std::printf(
                "image %s: mean %.3g max %.0f (white: %.0f) PSNR %.2f dB, %.2f%% pixels over %u\n",
                image.c_str(), d.mean, d.max, d.scale, d.psnr, d.over_threshold_percent,
                d.threshold);
    }
    if (json)
        std::cout << out.dump(2) << "\n";
    else
        print_text(c);
    return kExitOk;
}

} // namespace sherpa::cli
