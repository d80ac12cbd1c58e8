// sherpa-cli info SCENE [--json] [--scene N] [--animation N] [--time T]
#include "cli_common.h"
#include "motion_json.h"
#include "scene_json.h"
#include "texture_cli.h"

#include <sherpa/scene/scene_loader.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace sherpa::cli {
namespace {

void print_text(const Scene& s, const std::vector<tex::ImageProblem>& problems) {
    const SourceCounts& c = s.counts;
    const UsageReport usage = build_usage_report(s);
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
    if (s.bounds.valid())
        std::printf("  bounds [%g %g %g] .. [%g %g %g]\n", s.bounds.min.x, s.bounds.min.y,
                    s.bounds.min.z, s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
    else
        std::printf("  bounds: empty (nothing drawable)\n");
    std::printf("  vertex bytes: %llu for used streams vs %llu unified (56 B/vertex)\n",
                (unsigned long long)usage.used_bytes, (unsigned long long)usage.unified_bytes);
    std::printf("  timings: parse %.2f ms, process %.2f ms\n", s.parse_ms, s.process_ms);
    for (const auto& p : problems) std::printf("  warning: texture %s\n", tex::describe(p).c_str());
    print_motion_text(s);
    for (const auto& w : s.warnings) std::printf("  warning: %s\n", w.c_str());
}

constexpr const char* kUsage =
    "usage: sherpa-cli info SCENE [--json] [--scene N] [--animation N] [--time T]\n";

bool parse_int(std::string_view v, std::int32_t& out) {
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
    return ec == std::errc{} && end == v.data() + v.size() && out >= 0;
}

// A finite time in seconds (std::from_chars for double accepts "nan" and "inf").
bool parse_time(std::string_view v, double& out) {
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
    return ec == std::errc{} && end == v.data() + v.size() && std::isfinite(out);
}

} // namespace

int run_info(Args args) {
    std::string_view spec;
    bool as_json = false;
    LoadOptions options;
    std::int32_t animation = -1;
    double time = 0.0;
    bool posed = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json")
            as_json = true;
        else if (args[i] == "--scene" && i + 1 < args.size()) {
            if (!parse_int(args[++i], options.scene_index)) {
                std::fprintf(stderr, "error: --scene needs a non-negative integer\n");
                return kExitUsage;
            }
        } else if (args[i] == "--animation" && i + 1 < args.size()) {
            if (!parse_int(args[++i], animation)) {
                std::fprintf(stderr, "error: --animation needs a non-negative integer\n");
                return kExitUsage;
            }
        } else if (args[i] == "--time" && i + 1 < args.size()) {
            if (!parse_time(args[++i], time)) {
                std::fprintf(stderr, "error: --time needs a finite number of seconds\n");
                return kExitUsage;
            }
            posed = true;
        } else if (!args[i].empty() && args[i][0] == '-') {
            std::fprintf(stderr, "error: unknown option '%.*s'\n%s",
                         static_cast<int>(args[i].size()), args[i].data(), kUsage);
            return kExitUsage;
        } else if (spec.empty())
            spec = args[i];
        else {
            std::fprintf(stderr, "error: more than one SCENE given\n");
            return kExitUsage;
        }
    }
    if (spec.empty()) {
        std::fprintf(stderr, "%s", kUsage);
        return kExitUsage;
    }
    LoadResult r = load_scene(spec, options);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    const Scene& scene = *r.scene;
    if (animation >= 0 && !posed) {
        std::fprintf(stderr, "error: --animation needs --time T\n");
        return kExitUsage;
    }
    if (animation >= static_cast<std::int32_t>(scene.animations.size())) {
        std::fprintf(stderr, "error: %s: --animation %d out of range (the file has %zu)\n",
                     scene.source.c_str(), animation, scene.animations.size());
        return kExitUsage;
    }
    // Without --animation: the first animation, or the default weights when there is none.
    if (posed && animation < 0 && !scene.animations.empty()) animation = 0;
    const std::vector<tex::ImageProblem> problems = tex::find_image_problems(scene);
    if (as_json) {
        nlohmann::json j = scene_info_json(scene);
        j["image_problems"] = nlohmann::json::array();
        for (const auto& p : problems) j["image_problems"].push_back(image_problem_json(p));
        if (posed) j.update(posed_json(scene, pose_report(scene, animation, time)));
        std::cout << j.dump(2) << "\n";
    } else {
        print_text(scene, problems);
        if (posed) print_posed_text(pose_report(scene, animation, time));
    }
    return kExitOk;
}

} // namespace sherpa::cli
