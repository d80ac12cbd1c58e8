// sherpa-cli rt SCENE [--json] [--validation] [--scratch-budget BYTES] [--no-compact]
//                     [--rt on|off]
// The scene's ray-tracing data on the device: per BLAS (one per glTF mesh) its
// geometries, triangles, build time, size before and after compaction and scratch;
// the TLAS instances (deduplicated, mirrored, hidden, non-finite), the posed copies
// and BLAS of instances that skin or morph, and memory totals. A scene that skins or
// morphs is loaded into a ray-tracing Renderer, which poses it (the file's default
// pose) on load as every renderer does: the figures are those of what is drawn, posed
// instances in the TLAS included. Textures are not prepared: acceleration structures
// do not read them.
#include "cli_common.h"
#include "gpu_cli.h"

#include <sherpa/gpu/bindless.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/texture_pipeline.h>

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

int usage_error(const std::string& message) {
    return cli::usage_error(message, "rt"); // main.cpp's usage text
}

double ratio(std::uint64_t after, std::uint64_t before) {
    return before ? double(after) / double(before) : 1.0;
}

// Triangles per second of GPU build time, in millions, over the static BLAS built and
// timed (0 when none was).
double mtris_per_s(const render::AccelerationStats& s) {
    double ms = 0.0;
    std::uint64_t triangles = 0;
    for (const render::BlasStats& b : s.blas)
        if (b.built && b.build_ms > 0.0) ms += b.build_ms, triangles += b.triangles;
    return ms > 0.0 ? double(triangles) / (ms * 1e3) : 0.0;
}

// The same for the posed BLAS's last build or refit (0 when untimed).
double posed_mtris_per_s(const render::PosedStats& p) {
    return p.blas_ms > 0.0 ? double(p.triangles) / (p.blas_ms * 1e3) : 0.0;
}

std::uint64_t built_blas(const render::AccelerationStats& s) {
    std::uint64_t n = 0;
    for (const render::BlasStats& b : s.blas) n += b.built ? 1 : 0;
    return n;
}

nlohmann::json to_json(const gpu::Context& context, const render::AccelerationStats& s) {
    nlohmann::json blas = nlohmann::json::array();
    for (const render::BlasStats& b : s.blas)
        blas.push_back({{"mesh", b.mesh},
                        {"name", b.name},
                        {"geometries", b.geometries},
                        {"opaque_geometries", b.opaque_geometries},
                        {"culls_back_faces", b.culls_back_faces},
                        {"triangles", b.triangles},
                        {"first_geometry", b.first_geometry},
                        {"built", b.built},
                        {"batch", b.batch},
                        {"build_ms", b.build_ms},
                        {"build_bytes", b.build_bytes},
                        {"compacted_bytes", b.compacted_bytes},
                        {"scratch_bytes", b.scratch_bytes}});
    const render::TlasStats& t = s.tlas;
    const render::PosedStats& p = s.posed;
    return {{"device",
             {{"name", context.info().name},
              {"ray_tracing_enabled", context.info().ray_tracing_enabled},
              {"ray_query_enabled", context.info().ray_query_enabled}}},
            {"blas", blas},
            {"tlas",
             {{"node_mesh_pairs", t.node_mesh_pairs},
              {"instances", t.instances},
              {"deduplicated", t.deduplicated},
              {"mirrored", t.mirrored},
              {"hidden", t.hidden},
              {"non_finite", t.non_finite},
              {"bytes", t.bytes},
              {"scratch_bytes", t.scratch_bytes},
              {"instance_buffer_bytes", t.instance_buffer_bytes},
              {"build_ms", t.build_ms}}},
            {"posed",
             {{"blas", p.blas},
              {"geometries", p.geometries},
              {"world_space", p.world_space},
              {"vertices", p.vertices},
              {"triangles", p.triangles},
              {"stream_bytes", p.stream_bytes},
              {"blas_bytes", p.blas_bytes},
              {"scratch_bytes", p.scratch_bytes},
              {"update", p.refit ? "refit" : "rebuild"},
              {"updates", p.updates},
              {"pose_ms", p.pose_ms},
              {"blas_ms", p.blas_ms},
              {"mtriangles_per_s", posed_mtris_per_s(p)}}},
            {"totals",
             {{"blas", s.blas.size()},
              {"blas_built", built_blas(s)},
              {"posed_blas", p.blas},
              {"triangles", s.blas_triangles()},
              {"blas_build_bytes", s.blas_build_bytes()},
              {"blas_compacted_bytes", s.blas_compacted_bytes()},
              {"compaction_ratio", ratio(s.blas_compacted_bytes(), s.blas_build_bytes())},
              {"geometry_records", s.geometry_records},
              {"geometry_record_bytes", s.geometry_record_bytes},
              {"total_bytes", s.total_bytes()},
              {"batches", s.batches},
              {"scratch_budget", s.scratch_budget},
              {"scratch_buffer_bytes", s.scratch_buffer_bytes},
              {"blas_mtriangles_per_s", mtris_per_s(s)},
              {"build_wall_ms", s.build_wall_ms}}},
            {"warnings", s.warnings}};
}

void print_text(const gpu::Context& context, const render::AccelerationStats& s) {
    std::printf("device: %s (ray query %s)\n", context.info().name.c_str(),
                context.info().ray_query_enabled ? "enabled" : "absent");
    std::printf("%-5s %-24s %6s %8s %10s %9s %12s %12s %6s %12s %5s\n", "mesh", "name", "geoms",
                "no-AH", "triangles", "build ms", "built B", "compacted B", "ratio", "scratch B",
                "batch");
    for (const render::BlasStats& b : s.blas) {
        std::printf("%-5u %-24.24s %6u %8u %10llu ", b.mesh, b.name.c_str(), b.geometries,
                    b.opaque_geometries, (unsigned long long)b.triangles);
        if (!b.built) {
            std::printf("not built: every instance skins or morphs (posed BLAS below)\n");
            continue;
        }
        if (b.build_ms >= 0.0)
            std::printf("%9.3f ", b.build_ms);
        else
            std::printf("%9s ", "-");
        std::printf("%12llu %12llu %6.3f %12llu %5u\n", (unsigned long long)b.build_bytes,
                    (unsigned long long)b.compacted_bytes, ratio(b.compacted_bytes, b.build_bytes),
                    (unsigned long long)b.scratch_bytes, b.batch);
    }
    std::printf("  no-AH: geometries built with VK_GEOMETRY_OPAQUE_BIT, which skip the any-hit "
                "shader: opaque AND double-sided materials only (single-sided ones run any-hit "
                "to cull back faces, masked and blended ones for alpha)\n");
    const render::PosedStats& p = s.posed;
    if (p.blas) {
        std::printf("posed BLAS (skinned or morphed instances, default pose): %llu BLAS (%llu in "
                    "world space), %llu geometries, %llu vertices, %llu triangles; streams %llu "
                    "B, BLAS %llu B, scratch %llu B; ",
                    (unsigned long long)p.blas, (unsigned long long)p.world_space,
                    (unsigned long long)p.geometries, (unsigned long long)p.vertices,
                    (unsigned long long)p.triangles, (unsigned long long)p.stream_bytes,
                    (unsigned long long)p.blas_bytes, (unsigned long long)p.scratch_bytes);
        // The GPU time of the BLAS builds; posing's time (pose_ms in --json) includes
        // the first pose's set-up on load.
        if (p.blas_ms >= 0.0)
            std::printf("BLAS build %.3f ms (%.2f M triangles/s); ", p.blas_ms,
                        posed_mtris_per_s(p));
        std::printf("%s on pose changes\n", p.refit ? "refit" : "rebuilt");
    }
    const render::TlasStats& t = s.tlas;
    std::printf("TLAS: %llu instances of %llu (node, mesh) pairs%s: %llu deduplicated, %llu "
                "mirrored, %llu hidden, %llu non-finite; %llu B, scratch %llu B, instances %llu "
                "B, build %.3f ms\n",
                (unsigned long long)t.instances, (unsigned long long)t.node_mesh_pairs,
                p.blas ? " (posed instances included)" : "", (unsigned long long)t.deduplicated,
                (unsigned long long)t.mirrored, (unsigned long long)t.hidden,
                (unsigned long long)t.non_finite, (unsigned long long)t.bytes,
                (unsigned long long)t.scratch_bytes, (unsigned long long)t.instance_buffer_bytes,
                t.build_ms);
    std::printf("totals: %llu static BLAS built of %zu meshes, %llu posed BLAS, %llu triangles; "
                "static BLAS %llu -> %llu B compacted (%.3f), %llu geometry records (%llu B), "
                "%llu B in all; ",
                (unsigned long long)built_blas(s), s.blas.size(), (unsigned long long)p.blas,
                (unsigned long long)(s.blas_triangles()), (unsigned long long)s.blas_build_bytes(),
                (unsigned long long)s.blas_compacted_bytes(),
                ratio(s.blas_compacted_bytes(), s.blas_build_bytes()),
                (unsigned long long)s.geometry_records, (unsigned long long)s.geometry_record_bytes,
                (unsigned long long)s.total_bytes());
    if (built_blas(s))
        std::printf("static builds: %u batch(es) under a %llu B scratch budget (scratch buffer "
                    "%llu B), %.2f M triangles/s; ",
                    s.batches, (unsigned long long)s.scratch_budget,
                    (unsigned long long)s.scratch_buffer_bytes, mtris_per_s(s));
    std::printf("%.1f ms wall\n", s.build_wall_ms);
}

} // namespace

int run_rt(Args args) {
    std::string_view spec;
    bool as_json = false, validation = gpu::ContextOptions::default_validation(), rt = true;
    render::AccelerationSettings settings;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        if (a == "--json") {
            as_json = true;
        } else if (a == "--validation") {
            validation = true;
        } else if (a == "--no-compact") {
            settings.compact = false;
        } else if (a == "--scratch-budget") {
            std::uint64_t bytes = 0;
            const std::string_view v = i + 1 < args.size() ? args[++i] : std::string_view();
            if (!parse_number(v, bytes) || bytes == 0)
                return usage_error("--scratch-budget needs a positive number of bytes");
            settings.scratch_budget = bytes;
        } else if (a == "--rt") {
            const std::string_view v = i + 1 < args.size() ? args[++i] : std::string_view();
            if (v != "on" && v != "off") return usage_error("--rt needs on or off");
            rt = v == "on";
        } else if (!a.empty() && a[0] == '-') {
            return usage_error("unknown option '" + std::string(a) + "'");
        } else if (spec.empty()) {
            spec = a;
        } else {
            return usage_error("more than one SCENE given");
        }
    }
    if (spec.empty()) return usage_error("no SCENE given");
    scene::LoadResult loaded = scene::load_scene(spec);
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return kExitLoadError;
    }
    try {
        gpu::ContextOptions options;
        options.validation = validation;
        options.echo_validation = true;
        options.ray_tracing = rt;
        gpu::Context context(options);
        if (!context.info().ray_tracing_enabled) {
            std::fprintf(stderr, "error: %s: ray tracing is %s\n", context.info().name.c_str(),
                         rt ? "not supported by the device" : "off (--rt off)");
            return kExitLoadError;
        }
        const auto report = [&](const render::AccelerationStats& stats) {
            for (const auto& w : stats.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
            if (as_json)
                std::cout << to_json(context, stats).dump(1) << "\n";
            else
                print_text(context, stats);
        };
        // No textures: the structures read positions and indices only.
        const auto no_textures = std::make_shared<const tex::PreparedTextureSet>();
        if (!loaded.scene->motions.empty()) {
            // Posed instances join the TLAS once posed: the Renderer does that on load.
            render::RendererOptions renderer_options;
            renderer_options.ray_tracing = true;
            renderer_options.acceleration = settings;
            render::Renderer renderer(context, renderer_options);
            render::SceneSetup setup;
            setup.missing_textures = render::MissingTextures::Neutral;
            renderer.load(*loaded.scene, no_textures, setup);
            report(*renderer.resident().acceleration);
        } else {
            gpu::ResourceManager resources(context);
            gpu::BindlessTable table(resources);
            {
                render::GpuScene scene(resources, table, *loaded.scene, no_textures,
                                       render::StreamPolicy::UsedByMaterials,
                                       render::MissingTextures::Neutral);
                render::SceneAccelerationStructures structures(resources, *loaded.scene, scene,
                                                               settings);
                report(structures.stats());
            }
            resources.flush();
        }
        if (validation_failed(context, validation)) return kExitLoadError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %.*s: %s\n", int(spec.size()), spec.data(), e.what());
        return kExitLoadError;
    }
    return kExitOk;
}

} // namespace sherpa::cli
