// sherpa-cli cull SCENE [--camera CAMERA] [--method sphere|pvertex|exact|gpu] [--json]
//   [--animation N --time T | --pose bind]
// The camera pass plus one pass per shadow cascade of the scene's first
// directional light (or a default sun): the cascades the renderer draws for this
// camera (sherpa/scene/shadow_cascades.h), casters only.
#include "cli_camera.h"
#include "cli_common.h"
#include "pose_options.h"
#include "scene_json.h"

#include <sherpa/render/camera.h>
#include <sherpa/render/cull_check.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/scene/shadow_cascades.h>

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

constexpr std::string_view kUsage = "cull"; // main.cpp's usage text
// Without a viewport, `auto` and glTF cameras without an aspect use the camera
// string's default aspect.
constexpr float kCullAspect = 16.0f / 9.0f;

nlohmann::json pass_json(const scene::Scene& s, const scene::PassResult& p) {
    nlohmann::json visible = nlohmann::json::array();
    auto add = [&](std::uint32_t i) {
        const scene::MeshInstance& inst = s.instances[i];
        const scene::Mesh& m = s.meshes[inst.mesh_id];
        visible.push_back({inst.node_id, m.group_id, m.primitive_index});
    };
    for (std::uint32_t i : p.visible_opaque) add(i);
    for (std::uint32_t i : p.visible_transparent) add(i);
    nlohmann::json stats = cull_stats_json(p.stats);
    nlohmann::json matrix = stats["cull_view_projection"];
    stats.erase("cull_view_projection");
    return {{"name", p.stats.pass},
            {"cull_view_projection", matrix},
            {"visible", visible},
            {"stats", stats}};
}

} // namespace

int run_cull(Args args) {
    std::string_view spec, camera_text = "auto", method_text = "pvertex";
    bool as_json = false;
    PoseOptions pose_options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string pose_error;
        const OptionMatch pm = parse_pose_option(args, i, pose_options, pose_error);
        if (pm == OptionMatch::Bad) return usage_error(pose_error, kUsage);
        if (pm == OptionMatch::Taken) continue;
        if (args[i] == "--json")
            as_json = true;
        else if (args[i] == "--camera" && i + 1 < args.size())
            camera_text = args[++i];
        else if (args[i] == "--method" && i + 1 < args.size())
            method_text = args[++i];
        else if (!args[i].empty() && args[i][0] != '-' && spec.empty())
            spec = args[i];
        else
            return usage_error("unexpected argument '" + std::string(args[i]) + "'", kUsage);
    }
    if (spec.empty()) return usage_error("no SCENE given", kUsage);
    // The renderer's parser: auto, gltf:N and explicit cameras, as `render` takes them.
    render::CameraSpec camera_spec;
    std::string error;
    if (!render::parse_camera_spec(camera_text, camera_spec, error))
        return usage_error(error, kUsage);
    scene::CullOptions options;
    options.count_false_positives = true;
    const bool on_gpu = method_text == "gpu";
    if (on_gpu)
        options.method = scene::CullMethod::PVertex; // the GPU runs the p-vertex test
    else if (!scene::parse_cull_method(method_text, options.method)) {
        return usage_error("unknown method '" + std::string(method_text) + "'", kUsage);
    }
    const scene::LoadResult r = scene::load_scene(spec);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return kExitLoadError;
    }
    // Posed: every instance culled with its conservative bounds in that pose.
    const std::shared_ptr<const scene::Pose> pose = resolve_pose(*r.scene, pose_options, error);
    if (pose)
        scene::apply_pose_bounds(*r.scene, *pose);
    else if (!error.empty())
        return usage_error(error, kUsage);
    const scene::Scene& s = *r.scene;
    if (const std::string w = default_pose_warning(s, pose_options); !w.empty())
        std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (const std::string hint = file_camera_hint(s, camera_spec); !hint.empty())
        std::fprintf(stderr, "note: %s\n", hint.c_str());
    render::CameraView camera;
    try {
        camera = render::resolve_camera(framed_camera(camera_spec, s, pose.get(), kCullAspect), s,
                                        kCullAspect);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "error: %.*s: %s\n", int(spec.size()), spec.data(), e.what());
        return kExitLoadError;
    }
    const glm::mat4 view_projection = camera.proj * camera.view;
    const scene::CullInput input = scene::prepare_cull_input(s);
    std::vector<scene::PassResult> passes;
    passes.push_back(scene::cull_pass(input, scene::frustum_from_view_projection(view_projection),
                                      camera.position, options, "camera"));
    // The renderer's cascades for this camera (same fit, light, bounds and defaults),
    // each culled against its volume extended toward the light; casters only.
    std::vector<std::pair<std::string, scene::Frustum>> frusta = {
        {"camera", scene::frustum_from_view_projection(view_projection)}};
    std::vector<glm::mat4> matrices = {view_projection};
    if (const auto sun = scene::main_light_direction(s)) {
        const scene::ShadowCascades cascades = scene::fit_shadow_cascades(
            render::cascade_camera(camera), scene::drawable_bounds(s), *sun,
            scene::kDefaultShadowCascades, scene::kDefaultShadowResolution);
        scene::CullOptions shadow = options;
        shadow.casters_only = true;
        for (std::uint32_t c = 0; c < cascades.count; ++c) {
            frusta.emplace_back("cascade" + std::to_string(c),
                                scene::frustum_from_view_projection(cascades.cull_view_proj[c]));
            matrices.push_back(cascades.cull_view_proj[c]);
            passes.push_back(scene::cull_pass(input, frusta.back().second, camera.position, shadow,
                                              frusta.back().first));
        }
    }
    if (on_gpu) {
        std::vector<scene::PassResult> gpu_passes;
        if (!render::gpu_cull_passes(s, frusta, passes, gpu_passes, error)) {
            std::fprintf(stderr, "error: %s\n", error.c_str());
            return kExitLoadError;
        }
        passes = std::move(gpu_passes);
    }
    if (as_json) {
        nlohmann::json j = {{"passes", nlohmann::json::array()}};
        for (std::size_t p = 0; p < passes.size(); ++p) {
            passes[p].stats.view_projection = matrices[p];
            j["passes"].push_back(pass_json(s, passes[p]));
        }
        std::cout << j.dump(1) << "\n";
    } else {
        std::printf("%-9s %8s %9s %9s %8s %8s %6s %10s %8s %8s %8s\n", "pass", "method", "total",
                    "visible", "culled", "falsepos", "draws", "triangles", "cpu ms", "gpu ms",
                    "cpu!=gpu");
        for (const auto& p : passes) {
            const scene::CullStats& st = p.stats;
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
