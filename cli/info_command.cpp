// sherpa-cli info SCENE [--json] [--scene N]
#include "cli_common.h"
#include "scene_json.h"
#include "texture_cli.h"

#include <sherpa/scene/scene_loader.h>

#include <charconv>
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
    for (const auto& w : s.warnings) std::printf("  warning: %s\n", w.c_str());
}

} // namespace

int run_info(Args args) {
    std::string_view spec;
    bool as_json = false;
    LoadOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json")
            as_json = true;
        else if (args[i] == "--scene" && i + 1 < args.size()) {
            const std::string_view v = args[++i];
            const auto [end, ec] =
                std::from_chars(v.data(), v.data() + v.size(), options.scene_index);
            if (ec != std::errc{} || end != v.data() + v.size() || options.scene_index < 0) {
                std::fprintf(stderr, "error: --scene needs a non-negative integer\n");
                return kExitUsage;
            }
        } else if (!args[i].empty() && args[i][0] == '-') {
            std::fprintf(
                stderr,
                "error: unknown option '%.*s'\nusage: sherpa-cli info SCENE [--json] [--scene N]\n",
                static_cast<int>(args[i].size()), args[i].data());
            return kExitUsage;
        } else if (spec.empty())
            spec = args[i];
        else {
            std::fprintf(stderr, "error: more than one SCENE given\n");
            return kExitUsage;
        }
    }
    if (spec.empty()) {
        std::fprintf(stderr, "usage: sherpa-cli info SCENE [--json] [--scene N]\n");
        return kExitUsage;
    }
    LoadResult r = load_scene(spec, options);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    const std::vector<tex::ImageProblem> problems = tex::find_image_problems(*r.scene);
    if (as_json) {
        nlohmann::json j = scene_info_json(*r.scene);
        j["image_problems"] = nlohmann::json::array();
        for (const auto& p : problems) j["image_problems"].push_back(image_problem_json(p));
        std::cout << j.dump(2) << "\n";
    } else {
        print_text(*r.scene, problems);
    }
    return kExitOk;
}

} // namespace sherpa::cli
