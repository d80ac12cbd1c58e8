// sherpa-bench-render [--frames N] [--width W --height H] [--csv] [--no-prepass|--prepass]
//                     [--no-shadows] [--view NAME] [--quick] [--lit-only] [--no-bc] [SCENE...]
// Per scene: median frame time of the full renderer (lit view, all passes) next to
// a floor measured in the same run on the same device: the same triangles drawn
// with positions only and a constant colour. Also the lit frame with the shadow
// cascades re-rendered every frame (normally they are cached while camera, light
// and scene stay unchanged). Frame time = submit to completion, wall clock; the
// first two frames (pipeline compilation, first shadow map) are not counted. The
// CPU columns are process CPU time per frame (lavapipe's threads included): on a
// shared machine they move less than wall time does.
#include "process_cpu.h"

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace sherpa;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    if (v.empty()) return 0.0;
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct FrameTimes {
    double wall_ms = 0.0; // median wall clock per frame
    double cpu_ms = 0.0;  // mean CPU time per frame, all threads (less sensitive to a busy machine)
};

FrameTimes measure(render::Renderer& renderer, const render::FrameRequest& s, int frames) {
    std::vector<double> ms;
    double cpu0 = 0.0;
    for (int f = 0; f < frames + 2; ++f) {
        if (f == 2) cpu0 = bench::process_cpu_ms();
        const auto t0 = std::chrono::steady_clock::now();
        renderer.render(s);
        const double dt =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        if (f >= 2) ms.push_back(dt);
    }
    return {median(ms), (bench::process_cpu_ms() - cpu0) / frames};
}

std::vector<std::string> default_scenes() {
    std::vector<std::string> out{"builtin:default"};
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(fs::path(SHERPA_ASSETS_DIR) / "gltf"))
        if (fs::exists(e.path() / "glTF" / (e.path().filename().string() + ".gltf")))
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    for (const auto& n : names)
        out.push_back((fs::path(SHERPA_ASSETS_DIR) / "gltf" / n / "glTF" / (n + ".gltf")).string());
    return out;
}

} // namespace

int main(int argc, char** argv) {
    // What sherpa-cli and the editor do: lavapipe's per-frame blocks stay mapped.
    sherpa::core::keep_freed_memory_mapped();
    int frames = 20;
    bool csv = false, quick = false, lit_only = false, no_bc = false;
    render::FrameRequest lit;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--width") && i + 1 < argc)
            lit.width = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--height") && i + 1 < argc)
            lit.height = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--csv"))
            csv = true;
        else if (!std::strcmp(argv[i], "--no-prepass"))
            lit.depth_prepass = render::PrepassMode::Off;
        else if (!std::strcmp(argv[i], "--prepass"))
            lit.depth_prepass = render::PrepassMode::On;
        else if (!std::strcmp(argv[i], "--no-bc")) // RGBA8 textures, as render --no-bc
            no_bc = true;
        else if (!std::strcmp(argv[i], "--no-shadows"))
            lit.shadows = false;
        else if (!std::strcmp(argv[i], "--quick")) // skip the shadows-every-frame column
            quick = true;
        else if (!std::strcmp(argv[i], "--lit-only")) // for profilers: no floor, no shadow column
            lit_only = quick = true;
        else if (!std::strcmp(argv[i], "--view") && i + 1 < argc) {
            const auto v = render::parse_debug_view(argv[++i]);
            if (!v) {
                std::fprintf(stderr, "error: unknown view %s\n", argv[i]);
                return 2;
            }
            lit.view = *v;
        } else
            scenes.push_back(argv[i]);
    }
    if (scenes.empty()) scenes = default_scenes();

    gpu::ContextOptions options;
    options.validation = false; // the layer's CPU cost would distort frame times
    gpu::Context context(options);
    render::RendererOptions renderer_options; // as sherpa-cli render: the user's texture cache
    renderer_options.textures.cache_dir = tex::default_cache_dir_from_environment();
    renderer_options.textures.force_rgba8 = no_bc;
    render::Renderer renderer(context, renderer_options);
    std::printf("device: %s, %ux%u, median of %d frames\n", context.info().name.c_str(), lit.width,
                lit.height, frames);
    if (csv)
        std::printf("scene,triangles,floor_ms,lit_ms,ratio,lit_fps,lit_shadows_each_frame_ms,floor_"
                    "cpu_ms,lit_cpu_ms\n");
    else
        std::printf("%-26s %9s %9s %9s %6s %8s %13s %10s %8s\n", "scene", "triangles", "floor ms",
                    "lit ms", "ratio", "lit fps", "lit+shadow ms", "floor cpu", "lit cpu");
    for (const std::string& spec : scenes) {
        scene::LoadResult r = scene::load_scene(spec);
        if (!r) {
            std::fprintf(stderr, "error: %s\n", r.error.c_str());
            continue;
        }
        renderer.load(*r.scene);
        render::FrameRequest floor = lit;
        floor.floor_only = true;
        render::FrameRequest uncached = lit;
        uncached.cache_shadows = false;
        const FrameTimes floor_t = lit_only ? FrameTimes{} : measure(renderer, floor, frames);
        const FrameTimes lit_t = measure(renderer, lit, frames);
        const double shadow_ms = quick ? 0.0 : measure(renderer, uncached, frames).wall_ms;
        const double floor_ms = floor_t.wall_ms, lit_ms = lit_t.wall_ms;
        const std::string name =
            spec.rfind("builtin:", 0) == 0 ? spec : fs::path(spec).stem().string();
        const auto tris = static_cast<unsigned long long>(renderer.scene()->triangle_count());
        if (csv)
            std::printf("%s,%llu,%.2f,%.2f,%.2f,%.1f,%.2f,%.2f,%.2f\n", name.c_str(), tris,
                        floor_ms, lit_ms, lit_ms / floor_ms, 1000.0 / lit_ms, shadow_ms,
                        floor_t.cpu_ms, lit_t.cpu_ms);
        else
            std::printf("%-26s %9llu %9.2f %9.2f %6.2f %8.1f %13.2f %10.2f %8.2f\n", name.c_str(),
                        tris, floor_ms, lit_ms, lit_ms / floor_ms, 1000.0 / lit_ms, shadow_ms,
                        floor_t.cpu_ms, lit_t.cpu_ms);
        std::fflush(stdout);
        renderer.unload();
    }
    return 0;
}
