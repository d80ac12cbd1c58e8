#include "compare_options.h"
#include "environment_options.h"
#include "gpu_cli.h"

#include <sherpa/gpu/context.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

bool parse_float(std::string_view s, float& out) {
    return parse_number(s, out) && std::isfinite(out);
}

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

nlohmann::json side_json(const std::string& file, const render::FrameRequest& s) {
    return {{"file", file},
            {"renderer", to_string(s.renderer)},
            {"view", to_string(s.view)},
            {"texture_lod", s.texture_lod}};
}

std::string side_text(const std::string& file, const render::FrameRequest& s) {
    std::string out =
        file + " (" + std::string(to_string(s.renderer)) + ", " + std::string(to_string(s.view));
    if (s.texture_lod >= 0.0f) out += ", texture lod " + std::to_string(s.texture_lod);
    return out + ")";
}

} // namespace

OptionMatch parse_compare_option(Args args, std::size_t& i, CompareCliOptions& out,
                                 std::string& error) {
    const std::string_view a = args[i];
    if (a.substr(0, 9) != "--compare" && a != "--divider" && a != "--threshold" &&
        a != "--heat-max" && a != "--json")
        return OptionMatch::NotMine;
    if (a == "--json" || a == "--compare-no-bc") {
        (a == "--json" ? out.json : out.no_bc) = true;
        return OptionMatch::Taken;
    }
    if (i + 1 >= args.size()) {
        error = std::string(a) + " needs a value";
        return OptionMatch::Bad;
    }
    const std::string_view v = args[++i];
    float number = 0.0f;
    if (a == "--compare") {
        out.mode = render::parse_compare_mode(v);
        if (out.mode)
            out.compare.mode = *out.mode;
        else
            error = "--compare needs split or difference";
    } else if (a == "--compare-with") {
        out.with = std::string(v);
    } else if (a == "--compare-renderer") {
        out.renderer = render::parse_renderer(v);
        if (!out.renderer) error = "--compare-renderer needs raster or rt";
    } else if (a == "--compare-view") {
        out.view = render::parse_debug_view(v);
        if (!out.view) error = "--compare-view needs a view name (see --view)";
    } else if (a == "--compare-texture-lod") {
        if (v == "auto")
            out.texture_lod = -1.0f;
        else if (parse_float(v, number) && number >= 0.0f && number <= 16.0f)
            out.texture_lod = number;
        else
            error = "--compare-texture-lod needs a mip level from 0 to 16, or auto";
    } else if (a == "--compare-quality") {
        if (parse_float(v, number) && number >= 0.0f && number <= 4.0f &&
            number == std::floor(number))
            out.quality = int(number);
        else
            error = "--compare-quality needs a BC7 level 0 .. 4";
    } else if (a == "--divider") {
        if (parse_float(v, number) && number >= 0.0f && number <= 1.0f)
            out.compare.divider = number;
        else
            error = "--divider needs a fraction of the width from 0 to 1";
    } else if (a == "--threshold") {
        if (parse_float(v, number) && number >= 0.0f && number <= 255.0f)
            out.compare.threshold = number / 255.0f;
        else
            error = "--threshold needs 8-bit steps from 0 to 255";
    } else if (a == "--heat-max") {
        if (v == "auto")
            out.compare.heat_max = 0.0f;
        else if (parse_float(v, number) && number >= 1.0f && number <= 255.0f)
            out.compare.heat_max = number / 255.0f;
        else
            error = "--heat-max needs 8-bit steps from 1 to 255, or auto";
    } else {
        error = "unknown option '" + std::string(a) + "'";
    }
    return error.empty() ? OptionMatch::Taken : OptionMatch::Bad;
}

int run_comparison(const CompareRun& run, const CompareCliOptions& o) {
    render::FrameRequest sa = run.settings, sb = run.settings;
    render::SceneSetup setup_a = run.setup, setup_b = run.setup;
    if (o.renderer) sb.renderer = *o.renderer;
    if (o.view) sb.view = *o.view;
    if (o.texture_lod) sb.texture_lod = *o.texture_lod;
    const bool rt_a = sa.renderer == render::RendererKind::RayTraced;
    const bool rt_b = sb.renderer == render::RendererKind::RayTraced;
    if ((rt_a || rt_b) && !run.ray_tracing) {
        std::fprintf(stderr, "error: a ray-traced side needs --rt on\n");
        return kExitUsage;
    }
    scene::LoadResult other;
    const scene::Scene* scene_b = run.scene;
    if (!o.with.empty()) {
        other = scene::load_scene(o.with);
        if (!other) {
            std::fprintf(stderr, "error: %s\n", other.error.c_str());
            return kExitLoadError;
        }
        scene_b = other.scene.get();
        setup_b.hidden_nodes = nullptr; // --hide-node names side A's nodes: B as loaded
        // One camera for both: 'auto' frames side A's scene, not each its own.
        if (sa.camera.kind == render::CameraSpec::Kind::Auto) {
            scene::FramingOptions framing;
            framing.aspect = float(sa.width) / float(sa.height);
            sa.camera = sb.camera =
                render::explicit_camera(scene::frame_scene(*run.scene, sa.pose.get(), framing));
        }
    }
    const std::string file_b = o.with.empty() ? run.scene_name : o.with;
    render::ComparisonStats stats;
    std::vector<std::uint8_t> rgba;
    try {
        gpu::ContextOptions options;
        options.validation = run.validation;
        options.echo_validation = true;
        options.ray_tracing = run.ray_tracing;
        gpu::Context context(options);
        render::RendererOptions ra_options, rb_options;
        ra_options.ray_tracing = rt_a;
        rb_options.ray_tracing = rt_b;
        ra_options.textures = rb_options.textures = run.textures.gpu_settings();
        if (o.no_bc) rb_options.textures.force_rgba8 = true;
        if (o.quality) rb_options.textures.quality = *o.quality;
        render::Renderer a(context, ra_options), b(context, rb_options);
        setup_a.streams = render::stream_policy(sa);
        setup_b.streams = render::stream_policy(sb);
        // Both sides lit by one environment, as the render command's frame is; a side
        // that draws no lit view makes none (no GPU bytes).
        if (sa.view == render::DebugView::Lit || sb.view == render::DebugView::Lit) {
            const auto environment = make_environment_image(run.environment);
            if (sa.view == render::DebugView::Lit) a.set_environment(environment.get());
            if (sb.view == render::DebugView::Lit) b.set_environment(environment.get());
        }
        a.load(*run.scene, setup_a);
        b.load(*scene_b, setup_b);
        std::vector<double> reduce, composite;
        for (std::uint32_t f = 0; f < run.frames; ++f) {
            stats = render::render_comparison(a, sa, b, sb, o.compare,
                                              f + 1 == run.frames ? &rgba : nullptr);
            reduce.push_back(stats.reduce_ms);
            composite.push_back(stats.composite_ms);
        }
        stats.reduce_ms = median(reduce);
        stats.composite_ms = median(composite);
        if (validation_failed(context, run.validation)) return kExitLoadError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitLoadError;
    }
    std::string error;
    if (!tex::write_png(run.output, sa.width, sa.height, rgba, error)) {
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return kExitLoadError;
    }
    // In 8-bit steps (0..255), as `compare --image` reports them.
    const double threshold = std::round(double(o.compare.threshold) * 255.0 * 1000.0) / 1000.0;
    if (o.json) {
        nlohmann::json j{
            {"mode", to_string(*o.mode)},
            {"output", run.output},
            {"width", sa.width},
            {"height", sa.height},
            {"a", side_json(run.scene_name, sa)},
            {"b", side_json(file_b, sb)},
            {"pixels", stats.pixels},
            {"mean", stats.mean * 255.0},
            {"max", stats.max * 255.0},
            {"psnr_db", std::isfinite(stats.psnr_db) ? nlohmann::json(stats.psnr_db)
                                                     : nlohmann::json(nullptr)},
            {"threshold", threshold},
            {"over_threshold_percent", stats.over_threshold_percent},
            {"percentile_999", stats.percentile_999() * 255.0},
            {"pass_gpu_ms", {{"reduce", stats.reduce_ms}, {"composite", stats.composite_ms}}}};
        std::cout << j.dump(2) << "\n";
    } else {
        std::printf("%s: A %s vs B %s\n", std::string(to_string(*o.mode)).c_str(),
                    side_text(run.scene_name, sa).c_str(), side_text(file_b, sb).c_str());
        std::printf("difference (8-bit steps): mean %.4g max %.0f PSNR %.2f dB, %.2f%% of %llu "
                    "pixels over %g\n",
                    stats.mean * 255.0, stats.max * 255.0, stats.psnr_db,
                    stats.over_threshold_percent, static_cast<unsigned long long>(stats.pixels),
                    threshold);
        std::printf("comparison pass GPU time (median of %u): %.3f ms statistics, %.3f ms "
                    "composite\n",
                    run.frames, stats.reduce_ms, stats.composite_ms);
    }
    return kExitOk;
}

} // namespace sherpa::cli
