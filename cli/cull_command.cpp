// sherpa-cli cull SCENE --camera SPEC [--method sphere|pvertex|exact|gpu] [--json]
// The camera pass plus one pass per shadow cascade of the scene's first
// directional light (or a default sun).
#include "cli_common.h"
#include "cull_gpu.h"

#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/scene_loader.h>

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr const char* kUsage =
    "usage: sherpa-cli cull SCENE --camera "
    "eye=x,y,z:target=x,y,z[:up=..][:fov=DEG][:aspect=A][:near=N][:far=F]\n"
    "                          [--method sphere|pvertex|exact|gpu] [--json]\n";

nlohmann::json pass_json(const Scene& s, const PassResult& p) {
    nlohmann::json visible = nlohmann::json::array();
    auto add = [&](std::uint32_t i) {
        const MeshInstance& inst = s.instances[i];
        const Mesh& m = s.meshes[inst.mesh_id];
        visible.push_back({inst.node_id, m.group_id, m.primitive_index});
    };
    for (std::uint32_t i : p.visible_opaque) add(i);
    for (std::uint32_t i : p.visible_transparent) add(i);
    const CullStats& st = p.stats;
    return {{"name", st.pass},
            {"visible", visible},
            {"stats",
             {{"method", st.gpu ? std::string("gpu (") + std::string(to_string(st.method)) + ")"
                                : std::string(to_string(st.method))},
              {"gpu_ms", st.gpu_ms},
              {"cpu_gpu_differences", st.cpu_gpu_differences},
              {"simd", to_string(st.simd)},
              {"total", st.total},
              {"tested", st.tested},
              {"visible", st.visible},
              {"culled", st.culled},
              {"invalid", st.invalid},
              {"false_positives", st.false_positives},
              {"draw_calls", st.draw_calls},
              {"triangles", st.triangles},
              {"cpu_ms", st.cpu_ms}}}};
}

} // namespace

int run_cull(Args args) {
    std::string_view spec, camera_text, method_text = "pvertex";
    bool as_json = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json")
            as_json = true;
        else if (args[i] == "--camera" && i + 1 < args.size())
            camera_text = args[++i];
        else if (args[i] == "--method" && i + 1 < args.size())
            method_text = args[++i];
        else if (!args[i].empty() && args[i][0] != '-' && spec.empty())
            spec = args[i];
        else {
            std::fprintf(stderr, "error: unexpected argument '%.*s'\n%s",
                         static_cast<int>(args[i].size()), args[i].data(), kUsage);
            return kExitUsage;
        }
    }
    CameraSpec camera;
    std::string error;
    if (spec.empty() || camera_text.empty()) {
        std::fprintf(stderr, "%s", kUsage);
        return kExitUsage;
    }
    if (!parse_camera_spec(camera_text, camera, error)) {
        std::fprintf(stderr, "error: %s\n%s", error.c_str(), kUsage);
        return kExitUsage;
    }
    CullOptions options;
    options.count_false_positives = true;
    const bool on_gpu = method_text == "gpu";
    if (on_gpu)
        options.method = CullMethod::PVertex; // the GPU runs the p-vertex test
    else if (!parse_cull_method(method_text, options.method)) {
        std::fprintf(stderr, "error: unknown method '%.*s'\n%s",
                     static_cast<int>(method_text.size()), method_text.data(), kUsage);
        return kExitUsage;
    }
    const LoadResult r = load_scene(spec);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    const Scene& s = *r.scene;
    const CullInput input = prepare_cull_input(s);
    std::vector<PassResult> passes;
    passes.push_back(cull_pass(s, input, frustum_from_view_projection(camera.view_projection()),
                               camera.eye, options, "camera"));
    glm::vec3 sun{-0.4f, -1.0f, -0.3f};
    for (const PlacedLight& pl : s.placed_lights)
        if (s.lights[pl.light].type == LightType::Directional) {
            sun = pl.direction;
            break;
        }
    const auto cascades = cascade_view_projections(camera, sun, s.bounds, {});
    std::vector<std::pair<std::string, Frustum>> frusta = {
        {"camera", frustum_from_view_projection(camera.view_projection())}};
    for (std::size_t c = 0; c < cascades.size(); ++c) {
        frusta.emplace_back("cascade" + std::to_string(c),
                            frustum_from_view_projection(cascades[c]));
        passes.push_back(
            cull_pass(s, input, frusta.back().second, camera.eye, options, frusta.back().first));
    }
    if (on_gpu) {
        std::vector<PassResult> gpu_passes;
        if (!gpu_cull_passes(s, frusta, passes, gpu_passes, error)) {
            std::fprintf(stderr, "error: %s\n", error.c_str());
            return kExitLoadError;
        }
        passes = std::move(gpu_passes);
    }
    if (as_json) {
        nlohmann::json j = {{"passes", nlohmann::json::array()}};
        for (const auto& p : passes) j["passes"].push_back(pass_json(s, p));
        std::cout << j.dump(1) << "\n";
    } else {
        std::printf("%-9s %8s %9s %9s %8s %8s %6s %10s %8s %8s %8s\n", "pass", "method", "total",
                    "visible", "culled", "falsepos", "draws", "triangles", "cpu ms", "gpu ms",
                    "cpu!=gpu");
        for (const auto& p : passes) {
            const CullStats& st = p.stats;
            std::printf("%-9s %8s %9llu %9llu %8llu %8lld %6llu %10llu %8.3f %8.3f %8lld\n",
                        st.pass.c_str(), st.gpu ? "gpu" : std::string(to_string(st.method)).c_str(),
                        (unsigned long long)st.total, (unsigned long long)st.visible,
                        (unsigned long long)st.culled, (long long)st.false_positives,
                        (unsigned long long)st.draw_calls, (unsigned long long)st.triangles,
                        st.cpu_ms, st.gpu_ms, (long long)st.cpu_gpu_differences);
        }
    }
    return kExitOk;
}

} // namespace sherpa::cli
