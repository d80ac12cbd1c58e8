// sherpa-cli info SCENE [--json] [--scene N] [--animation N --time T | --pose bind]
//                      [--variant NAME]
#include "cli_common.h"
#include "motion_json.h"
#include "pose_options.h"
#include "scene_json.h"
#include "texture_cli.h"
#include "variant_options.h"

#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/scene_loader.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace sherpa::cli {
namespace {

// "  extensions used: KHR_texture_transform (supported), KHR_materials_clearcoat (NOT
// supported: not drawn)": the table of gltf_extensions.h, as info --json gives it.
void print_extensions(const char* which, const std::vector<std::string>& names) {
    if (names.empty()) return;
    std::printf("  extensions %s:", which);
    for (std::size_t i = 0; i < names.size(); ++i)
        std::printf("%s %s (%s)", i ? "," : "", names[i].c_str(),
                    scene::is_supported_gltf_extension(names[i]) ? "supported"
                                                                 : "NOT supported: not drawn");
    std::printf("\n");
}

void print_text(const scene::Scene& s, const std::vector<tex::ImageProblem>& problems) {
    const scene::SourceCounts& c = s.counts;
    const scene::UsageReport usage = scene::build_usage_report(s);
    std::printf("%s\n", s.source.c_str());
    std::printf("  scenes %llu (showing %d)  nodes %llu  meshes %llu  primitives %llu\n",
                (unsigned long long)c.scenes, s.displayed_scene, (unsigned long long)c.nodes,
                (unsigned long long)c.meshes, (unsigned long long)c.primitives);
    std::printf(
        "  materials %llu  textures %llu  images %llu  samplers %llu  lights %llu  cameras %llu\n",
        (unsigned long long)c.materials, (unsigned long long)c.textures,
        (unsigned long long)c.images, (unsigned long long)c.samplers, (unsigned long long)c.lights,
        (unsigned long long)c.cameras);
    std::printf("  instances %zu  vertices %llu  triangles %llu\n", s.instances.size(),
                (unsigned long long)c.vertices, (unsigned long long)c.triangles);
    if (const nlohmann::json g = gpu_instancing_json(s); !g.at("nodes").empty())
        std::printf("  gpu instancing: %zu node(s), %llu rows drawn of %llu -> %llu instances\n",
                    g.at("nodes").size(), g.at("drawn_rows").get<unsigned long long>(),
                    g.at("file_rows").get<unsigned long long>(),
                    g.at("instances").get<unsigned long long>());
    if (s.bounds.valid())
        std::printf("  bounds [%g %g %g] .. [%g %g %g]\n", s.bounds.min.x, s.bounds.min.y,
                    s.bounds.min.z, s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
    else
        std::printf("  bounds: empty (nothing drawable)\n");
    std::printf("  vertex bytes: %llu for used streams vs %llu unified (56 B/vertex)\n",
                (unsigned long long)usage.used_bytes, (unsigned long long)usage.unified_bytes);
    std::printf("  timings: parse %.2f ms, process %.2f ms, validate %.2f ms\n", s.parse_ms,
                s.process_ms, s.validation.ms);
    std::printf(
        "  validation: %zu errors, %zu warnings, %zu infos, %zu hints%s"
        "   (sherpa-cli validate lists them)\n",
        s.validation.count(scene::Severity::Error), s.validation.count(scene::Severity::Warning),
        s.validation.count(scene::Severity::Information), s.validation.count(scene::Severity::Hint),
        s.validation.truncated ? " (truncated)" : "");
    print_extensions("used", s.extensions_used);
    print_extensions("required", s.extensions_required);
    for (const auto& p : problems) std::printf("  warning: texture %s\n", tex::describe(p).c_str());
    print_motion_text(s);
    print_variants_text(s);
    for (const auto& w : s.warnings) std::printf("  warning: %s\n", w.c_str());
}

constexpr std::string_view kUsage = "info"; // main.cpp's usage text

} // namespace

int run_info(Args args) {
    std::string_view spec;
    bool as_json = false;
    scene::LoadOptions options;
    PoseOptions pose;
    std::string error, variant;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const OptionMatch m = parse_pose_option(args, i, pose, error);
        if (m == OptionMatch::Bad) return usage_error(error, kUsage);
        if (m == OptionMatch::Taken) continue;
        const OptionMatch vm = parse_variant_option(args, i, variant, error);
        if (vm == OptionMatch::Bad) return usage_error(error, kUsage);
        if (vm == OptionMatch::Taken) continue;
        if (args[i] == "--json")
            as_json = true;
        else if (args[i] == "--scene" && i + 1 < args.size()) {
            if (!parse_index(args[++i], options.scene_index))
                return usage_error("--scene needs a non-negative integer", kUsage);
        } else if (!args[i].empty() && args[i][0] == '-')
            return usage_error("unknown option '" + std::string(args[i]) + "'", kUsage);
        else if (spec.empty())
            spec = args[i];
        else
            return usage_error("more than one SCENE given", kUsage);
    }
    if (spec.empty()) return usage_error("no SCENE given", kUsage);
    scene::LoadResult r = scene::load_scene(spec, options);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    if (!apply_variant_option(*r.scene, variant, error)) return usage_error(error, kUsage);
    const scene::Scene& scene = *r.scene;
    std::int32_t animation = -1;
    if (!pose_animation(scene, pose, animation, error)) return usage_error(error, kUsage);
    const bool posed = pose.bind || pose.timed;
    const double time = pose.time;
    const std::vector<tex::ImageProblem> problems = tex::find_image_problems(scene);
    if (as_json) {
        nlohmann::json j = scene_info_json(scene);
        j["material_variants"] = variants_json(scene);
        j["image_problems"] = nlohmann::json::array();
        for (const auto& p : problems) j["image_problems"].push_back(image_problem_json(p));
        if (posed) j.update(posed_json(scene, pose_report(scene, animation, time)));
        std::cout << j.dump(2) << "\n";
    } else {
        print_text(scene, problems);
        if (posed) print_posed_text(scene, pose_report(scene, animation, time));
    }
    return kExitOk;
}

} // namespace sherpa::cli
