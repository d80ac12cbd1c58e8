// sherpa-cli render SCENE -o OUT.png [--width W --height H] [--view NAME]
//   [--overlay NAME ...] [--camera auto|gltf:N|eye=x,y,z:target=x,y,z[...]]
//   [--frames N] [--report FILE.json] [--validation] [--no-shadows] [--prepass|--no-prepass]
//   [--glyph-length L] [--floor] [--cache-dir DIR] [--cache-cap-mb N] [--quality N]
//   [--no-cache] [--no-bc] [--animation N --time T | --pose bind] [--hide-node N ...]
//   [--compare split|difference ... (compare_options.h)]
#include "cli_camera.h"
#include "cli_common.h"
#include "compare_options.h"
#include "environment_options.h"
#include "gpu_cli.h"
#include "pose_options.h"
#include "render_report.h"
#include "shadow_options.h"
#include "texture_cli.h"
#include "variant_options.h"
#include "view_legend.h"

#include <sherpa/core/file_io.h>
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/render/shadow_error.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/image.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

namespace sherpa::cli {
namespace {

int usage_error(const std::string& message) {
    return cli::usage_error(message, "render"); // main.cpp's usage text
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

std::string joined(const std::vector<std::string_view>& names) {
    std::string out;
    for (auto n : names) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

} // namespace

int run_render(Args args) {
    std::string_view spec, out_path, report_path;
    std::string camera_text = "auto";
    render::FrameRequest settings;
    std::uint32_t frames = 1;
    bool validation = gpu::ContextOptions::default_validation();
    std::vector<std::uint32_t> hidden_nodes; // --hide-node, in the order given
    bool ray_tracing = true;
    TextureCliOptions texture_options;
    PoseOptions pose_options;
    std::string variant; // --variant NAME
    CompareCliOptions compare_options;
    std::uint32_t shadow_resolution = scene::kDefaultShadowResolution;
    render::EnvironmentChoice environment; // the room unless --environment says otherwise
    settings.path.samples = 64;            // the path tracer's samples per pixel unless --spp says
    settings.path.restart = true;          // each of --frames is an image of its own
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        std::string option_error;
        const OptionMatch m = parse_texture_option(args, i, texture_options, option_error);
        if (m == OptionMatch::Bad) return usage_error(option_error);
        if (m == OptionMatch::Taken) continue;
        const OptionMatch pm = parse_pose_option(args, i, pose_options, option_error);
        if (pm == OptionMatch::Bad) return usage_error(option_error);
        if (pm == OptionMatch::Taken) continue;
        const OptionMatch vm = parse_variant_option(args, i, variant, option_error);
        if (vm == OptionMatch::Bad) return usage_error(option_error);
        if (vm == OptionMatch::Taken) continue;
        const OptionMatch cm = parse_compare_option(args, i, compare_options, option_error);
        if (cm == OptionMatch::Bad) return usage_error(option_error);
        if (cm == OptionMatch::Taken) continue;
        const OptionMatch sm =
            parse_shadow_option(args, i, settings, shadow_resolution, option_error);
        if (sm == OptionMatch::Bad) return usage_error(option_error);
        if (sm == OptionMatch::Taken) continue;
        const OptionMatch em =
            parse_environment_option(args, i, settings, environment, option_error);
        if (em == OptionMatch::Bad) return usage_error(option_error);
        if (em == OptionMatch::Taken) continue;
        auto value = [&]() -> std::optional<std::string_view> {
            if (i + 1 >= args.size()) return std::nullopt;
            return args[++i];
        };
        if (a == "-o" || a == "--output") {
            auto v = value();
            if (!v) return usage_error("-o needs a file name");
            out_path = *v;
        } else if (a == "--width" || a == "--height" || a == "--frames") {
            auto v = value();
            std::uint32_t n = 0;
            if (!v || !parse_number(*v, n) || n == 0 || n > 16384)
                return usage_error(std::string(a) + " needs a positive integer (at most 16384)");
            (a == "--width" ? settings.width : a == "--height" ? settings.height : frames) = n;
        } else if (a == "--view") {
            auto v = value();
            auto view = v ? render::parse_debug_view(*v) : std::nullopt;
            if (!view)
                return usage_error("--view needs one of: " + joined(render::debug_view_names()));
            settings.view = *view;
        } else if (a == "--overlay") {
            // One or more names; also accepted comma-separated or repeated.
            bool any = false;
            while (i + 1 < args.size() && !args[i + 1].empty() && args[i + 1][0] != '-') {
                std::string_view list = args[i + 1];
                bool all_known = true;
                for (std::size_t at = 0; at <= list.size();) {
                    const std::size_t comma = std::min(list.find(',', at), list.size());
                    if (!render::parse_overlay(list.substr(at, comma - at))) all_known = false;
                    at = comma + 1;
                }
                if (!all_known) break; // not an overlay name: the SCENE, probably
                for (std::size_t at = 0; at <= list.size();) {
                    const std::size_t comma = std::min(list.find(',', at), list.size());
                    settings.overlays |= *render::parse_overlay(list.substr(at, comma - at));
                    at = comma + 1;
                }
                any = true;
                ++i;
            }
            if (!any)
                return usage_error("--overlay needs one or more of: " +
                                   joined(render::overlay_names()));
        } else if (a == "--camera") {
            auto v = value();
            if (!v) return usage_error("--camera needs a spec");
            std::string error;
            if (!render::parse_camera_spec(*v, settings.camera, error)) return usage_error(error);
            camera_text = std::string(*v);
        } else if (a == "--report") {
            auto v = value();
            if (!v) return usage_error("--report needs a file name");
            report_path = *v;
        } else if (a == "--glyph-length") {
            auto v = value();
            if (!v || !parse_number(*v, settings.glyph_length) || !(settings.glyph_length > 0.0f))
                return usage_error("--glyph-length needs a positive number");
        } else if (a == "--cull") {
            auto v = value();
            const auto path = v ? render::parse_cull_path(*v) : std::nullopt;
            if (!path) return usage_error("--cull needs none, cpu or gpu");
            settings.cull = *path;
        } else if (a == "--cull-method") {
            auto v = value();
            if (!v || !scene::parse_cull_method(*v, settings.cull_method))
                return usage_error("--cull-method needs sphere, pvertex or exact");
        } else if (a == "--cull-check") {
            settings.cull_check = true;
        } else if (a == "--freeze-cull") {
            auto v = value();
            if (!v) return usage_error("--freeze-cull needs a camera spec");
            render::CameraSpec frozen;
            std::string error;
            if (!render::parse_camera_spec(*v, frozen, error)) return usage_error(error);
            settings.freeze_cull = frozen;
        } else if (a == "--validation") {
            validation = true;
        } else if (a == "--rt") {
            auto v = value();
            if (!v || (*v != "on" && *v != "off")) return usage_error("--rt needs on or off");
            ray_tracing = *v == "on";
        } else if (a == "--renderer") {
            auto v = value();
            const auto kind = v ? render::parse_renderer(*v) : std::nullopt;
            if (!kind) return usage_error("--renderer needs raster or rt");
            settings.renderer = *kind;
        } else if (a == "--texture-lod") {
            auto v = value();
            if (!v || !parse_number(*v, settings.texture_lod) || !(settings.texture_lod >= 0.0f) ||
                settings.texture_lod > 16.0f)
                return usage_error("--texture-lod needs a mip level from 0 to 16");
        } else if (a == "--hide-node") {
            auto v = value();
            std::uint32_t n = 0;
            if (!v || !parse_number(*v, n))
                return usage_error("--hide-node needs a node index (0 or more)");
            hidden_nodes.push_back(n);
        } else if (a == "--no-shadows") {
            settings.shadows = false;
        } else if (a == "--prepass") {
            settings.depth_prepass = render::PrepassMode::On;
        } else if (a == "--no-prepass") {
            settings.depth_prepass = render::PrepassMode::Off;
        } else if (a == "--floor") {
            settings.floor_only = true;
        } else if (!a.empty() && a[0] == '-') {
            return usage_error("unknown option '" + std::string(a) + "'");
        } else if (spec.empty()) {
            spec = a;
        } else {
            return usage_error("more than one SCENE given");
        }
    }
    if (spec.empty()) return usage_error("no SCENE given");
    if (out_path.empty()) return usage_error("no output given (-o OUT.png)");
    if (!compare_options.mode && (compare_options.side_b_changed() || compare_options.json))
        return usage_error("--compare-* and --json need --compare split|difference");
    const bool ray_traced = settings.renderer == render::RendererKind::RayTraced;
    if (ray_traced && !ray_tracing) return usage_error("--renderer rt needs --rt on");
    if (ray_traced && !render::ray_traced_view(settings.view))
        return usage_error("--renderer rt does not draw view '" +
                           std::string(to_string(settings.view)) + "'");
    if (ray_traced && settings.overlays != 0) return usage_error("--renderer rt draws no overlays");
    if (!ray_traced && !render::raster_view(settings.view))
        return usage_error("view '" + std::string(to_string(settings.view)) +
                           "' is drawn by rays only (--renderer rt)");

    const auto load_start = std::chrono::steady_clock::now();
    scene::LoadResult loaded = scene::load_scene(spec);
    RenderRun run{std::string(spec), settings, camera_text, {}, {}, {}, std::nullopt};
    run.timing.scene_load_ms = ms_since(load_start);
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return kExitLoadError;
    }
    {
        std::string error;
        if (!apply_variant_option(*loaded.scene, variant, error)) return usage_error(error);
        settings.pose = resolve_pose(*loaded.scene, pose_options, error);
        if (!error.empty()) return usage_error(error);
        run.settings.pose = settings.pose;
    }
    // Said before auto becomes the camera that frames what is drawn (posed, if asked).
    const std::string camera_hint = file_camera_hint(*loaded.scene, settings.camera);
    settings.camera = framed_camera(settings.camera, *loaded.scene, settings.pose.get(),
                                    float(settings.width) / float(settings.height));
    run.settings.camera = settings.camera;
    // What the load fixes: the streams the view reads, missing textures, hidden nodes.
    render::SceneSetup setup;
    setup.streams = render::stream_policy(settings);
    setup.missing_textures = texture_options.missing;
    if (!hidden_nodes.empty()) {
        auto mask = std::make_shared<std::vector<bool>>(loaded.scene->nodes.size(), false);
        for (const std::uint32_t n : hidden_nodes) {
            if (n >= mask->size())
                return usage_error("--hide-node " + std::to_string(n) + ": " + std::string(spec) +
                                   " has " + std::to_string(mask->size()) + " nodes");
            (*mask)[n] = true;
        }
        setup.hidden_nodes = mask;
    }
    if (compare_options.mode)
        return run_comparison({loaded.scene.get(), std::string(spec), settings, setup,
                               texture_options, validation, ray_tracing, std::string(out_path),
                               frames, environment},
                              compare_options);
    try {
        gpu::ContextOptions options;
        options.validation = validation;
        options.echo_validation = true;
        options.ray_tracing = ray_tracing;
        gpu::Context context(options);
        render::RendererOptions renderer_options;
        renderer_options.ray_tracing = ray_traced; // acceleration structures built on load
        renderer_options.shadow_resolution = shadow_resolution;
        render::Renderer renderer(context, renderer_options);
        // Only a lit frame is lit by it: other views make no environment (no GPU bytes).
        if (settings.view == render::DebugView::Lit && !settings.floor_only)
            apply_environment(renderer, environment);
        // Textures are prepared (cache lookups, decode, compression) before the upload,
        // as a loader thread would, so the report can time the two apart.
        const render::TextureSettings texture_settings = texture_options.gpu_settings();
        auto start = std::chrono::steady_clock::now();
        const auto textures = tex::prepare_scene_textures(
            *loaded.scene, render::texture_target(context.info(), texture_settings),
            render::texture_pipeline_options(texture_settings));
        run.timing.texture_prepare_ms = ms_since(start);
        start = std::chrono::steady_clock::now();
        renderer.load(*loaded.scene, textures, setup);
        run.timing.gpu_upload_ms = ms_since(start);
        run.cache_dir = texture_options.resolved_cache_dir();
        std::vector<std::uint8_t> rgba;
        for (std::uint32_t f = 0; f < frames; ++f) {
            const auto t0 = std::chrono::steady_clock::now();
            run.frames.push_back(renderer.render(settings, f + 1 == frames ? &rgba : nullptr));
            run.cpu_frame_ms.push_back(ms_since(t0));
        }
        // Device creation is left out: it is not the scene's cost.
        run.timing.load_and_first_frame_ms = run.timing.scene_load_ms +
                                             run.timing.texture_prepare_ms +
                                             run.timing.gpu_upload_ms + run.cpu_frame_ms.front();
        if (ray_traced && settings.view == render::DebugView::Lit) {
            const render::PathTraceError e = render::path_trace_error(renderer);
            const double ms = run.frames.back().gpu_ms;
            std::printf("path: %u spp in %.1f ms GPU (%.2f ms per sample), ", e.samples, ms,
                        e.samples ? ms / e.samples : 0.0);
            if (e.samples < 2)
                std::printf(
                    "estimated error: none (one sample has no variance; --spp 2 or more)\n");
            else
                std::printf("estimated error: mean standard error %.5f of mean luminance %.5f "
                            "(%.3f%%)\n",
                            e.mean_standard_error, e.mean_luminance, 100.0 * e.relative_error);
        }
        if (settings.view == render::DebugView::ShadowError) {
            // The view's pixel classes counted back (their colours are the engine's).
            const render::ShadowErrorCounts n = render::count_shadow_error(rgba);
            std::printf("shadow-error: %.3f%% of %llu lit pixels wrong (false shadow %llu, false "
                        "light %llu; agree lit %llu, agree shadowed %llu)\n",
                        n.percent_of_lit_wrong(), (unsigned long long)n.lit(),
                        (unsigned long long)n.false_shadow, (unsigned long long)n.false_light,
                        (unsigned long long)n.agree_lit, (unsigned long long)n.agree_shadowed);
        }
        // Views whose colours are classes carry their legend in the picture.
        if (const std::string legend = view_legend_line(settings.view); !legend.empty()) {
            const bool drawn =
                draw_view_legend(rgba, settings.width, settings.height, settings.view);
            std::printf("%s%s\n", legend.c_str(),
                        drawn ? " (legend drawn bottom left)" : " (image too small for a legend)");
        }
        std::string error;
        if (!tex::write_png(std::string(out_path), settings.width, settings.height, rgba, error)) {
            std::fprintf(stderr, "error: %s\n", error.c_str());
            return kExitLoadError;
        }
        // The importer's warnings, as info prints them (skipped objects, repaired data,
        // what the renderer leaves out: animations without --time, unused attributes), then the
        // texture pipeline's and the path tracer's: nothing the file holds is dropped without
        // a word.
        for (const auto& w : loaded.scene->warnings)
            std::fprintf(stderr, "warning: %s\n", w.c_str());
        if (const std::string w = default_pose_warning(*loaded.scene, pose_options); !w.empty())
            std::fprintf(stderr, "warning: %s\n", w.c_str());
        if (!camera_hint.empty()) std::fprintf(stderr, "note: %s\n", camera_hint.c_str());
        for (const auto& w : renderer.scene()->materials().textures().warnings())
            std::fprintf(stderr, "warning: %s\n", w.c_str());
        // The path tracer's light list: emitters it cannot sample as lights, and why.
        for (const auto& w : renderer.resident().emissive.warnings)
            std::fprintf(stderr, "warning: %s\n", w.c_str());
        if (!report_path.empty()) {
            const std::string text = render_report_json(renderer, run).dump(2) + "\n";
            if (!core::write_file_atomic(
                    std::string(report_path),
                    std::span<const std::uint8_t>(
                        reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
                    error)) {
                std::fprintf(stderr, "error: %s\n", error.c_str());
                return kExitLoadError;
            }
        }
        if (validation_failed(context, validation)) return kExitLoadError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitLoadError;
    }
    return kExitOk;
}

} // namespace sherpa::cli
