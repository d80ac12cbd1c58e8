// sherpa-bench-environment [--frames N] [--repeats N] [--width W --height H] [SCENE]
// Environment lighting on this device (lavapipe here), same-run ratios:
//  1. Prefiltering a 1024x512 EXR (Blender's studio lights, else the room at 1024x512):
//     upload + every compute pass, wall clock and process CPU time (lavapipe's
//     threads included: on a shared machine it moves less than wall time), per pass
//     by GPU timestamps. Goal: under 300 ms.
//  2. SCENE (default DamagedHelmet) lit at W x H (default 1280x720): the frame with the
//     environment (room) next to the frame without (the ambient term), and with the
//     environment behind a solid background (its lighting alone), alternating runs
//     so that machine load hits both alike. Goal: at most 1.3x.
//  3. No environment pays nothing: the frame before any environment was made and the
//     frame after it was removed, and the renderer's GPU bytes then (0).
#include "process_cpu.h"

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace sherpa;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

double now_ms() {
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// A frame's median wall time and process CPU time (every lavapipe thread): on a
// shared machine the CPU time moves far less with other work than the wall time.
struct FrameTime {
    double wall = 0.0, cpu = 0.0;
};

FrameTime frame_ms(gpu::Renderer& r, const gpu::FrameRequest& s, int frames) {
    r.render(s); // warm: pipelines, shadow cascades
    std::vector<double> wall, cpu;
    for (int i = 0; i < frames; ++i) {
        const double t0 = now_ms(), c0 = bench::process_cpu_ms();
        r.render(s);
        wall.push_back(now_ms() - t0);
        cpu.push_back(bench::process_cpu_ms() - c0);
    }
    return {median(wall), median(cpu)};
}

struct Runs {
    std::vector<double> wall, cpu;
    void add(FrameTime t) { wall.push_back(t.wall), cpu.push_back(t.cpu); }
    double w() const { return median(wall); }
    double c() const { return median(cpu); }
};

} // namespace

int main(int argc, char** argv) {
    keep_freed_memory_mapped();
    int frames = 5, repeats = 5;
    bool prefilter_only = false;
    gpu::FrameRequest s;
    std::string scene_spec =
        std::string(SHERPA_ASSETS_DIR) + "/gltf/DamagedHelmet/glTF/DamagedHelmet.gltf";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--repeats" && i + 1 < argc)
            repeats = std::max(1, std::atoi(argv[++i]));
        else if (a == "--width" && i + 1 < argc)
            s.width = std::uint32_t(std::atoi(argv[++i]));
        else if (a == "--height" && i + 1 < argc)
            s.height = std::uint32_t(std::atoi(argv[++i]));
        else if (a == "--prefilter-only")
            prefilter_only = true;
        else if (!a.empty() && a[0] != '-')
            scene_spec = a;
        else {
            std::fprintf(stderr, "usage: sherpa-bench-environment [--frames N] [--repeats N] "
                                 "[--width W --height H] [SCENE]\n");
            return 2;
        }
    }
    gpu::Context context;
    gpu::Renderer renderer(context);
    std::printf("device: %s\n", context.info().name.c_str());

    // 1. Prefilter.
    const auto lights = gpu::installed_studio_lights();
    gpu::EnvironmentImage image;
    const auto studio = std::find_if(lights.begin(), lights.end(), [](const std::string& f) {
        return f.size() >= 10 && f.compare(f.size() - 10, 10, "studio.exr") == 0;
    });
    image =
        studio != lights.end() ? gpu::load_environment(*studio).image : gpu::room_environment(1024);
    std::printf("prefilter %s (%ux%u), %d runs:\n", image.name.c_str(), image.width, image.height,
                repeats);
    std::vector<double> wall, cpu, gpu_ms, pass[5];
    for (int i = 0; i < repeats; ++i) {
        const double c0 = bench::process_cpu_ms();
        renderer.set_environment(&image);
        cpu.push_back(bench::process_cpu_ms() - c0);
        const gpu::EnvironmentStats st = renderer.resident().environment;
        wall.push_back(st.prefilter_ms);
        gpu_ms.push_back(st.gpu_ms);
        for (int p = 0; p < 5; ++p) pass[p].push_back(st.pass_ms[p]);
        renderer.set_environment(nullptr);
    }
    std::printf("  median wall %.1f ms, CPU %.1f ms (all threads), GPU passes %.1f ms "
                "[radiance cube %.1f, GGX %.1f, irradiance %.1f, Charlie %.1f, LUT %.1f]\n",
                median(wall), median(cpu), median(gpu_ms), median(pass[0]), median(pass[1]),
                median(pass[2]), median(pass[3]), median(pass[4]));
    std::printf("  goal < 300 ms: %s (wall)\n", median(wall) < 300.0 ? "met" : "NOT met");

    if (prefilter_only) return 0;

    // 2. and 3. Frames.
    LoadResult loaded = load_scene(scene_spec);
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return 1;
    }
    renderer.load(*loaded.scene);
    const FrameTime before = frame_ms(renderer, s, frames);
    const gpu::EnvironmentImage room = gpu::room_environment();
    Runs with, with_solid, without;
    gpu::FrameRequest solid = s;
    solid.background = gpu::Background::Color;
    for (int i = 0; i < repeats; ++i) {
        renderer.set_environment(&room);
        with.add(frame_ms(renderer, s, frames));
        with_solid.add(frame_ms(renderer, solid, frames));
        renderer.set_environment(nullptr);
        without.add(frame_ms(renderer, s, frames));
    }
    const std::uint64_t bytes_after = renderer.resident().environment.bytes;
    std::printf("%s lit %ux%u, median of %d frames x %d alternating runs (wall ms; CPU ms):\n",
                scene_spec.c_str(), s.width, s.height, frames, repeats);
    std::printf("  with the environment %.1f, without %.1f: %.2fx; CPU %.1f / %.1f: %.2fx "
                "(goal <= 1.3x)\n",
                with.w(), without.w(), with.w() / without.w(), with.c(), without.c(),
                with.c() / without.c());
    std::printf("  with the environment but a solid background (lighting alone) %.1f: %.2fx; "
                "CPU %.1f: %.2fx\n",
                with_solid.w(), with_solid.w() / without.w(), with_solid.c(),
                with_solid.c() / without.c());
    std::printf("  no environment, before any was made %.1f, after one was removed %.1f: "
                "%.2fx; CPU %.1f / %.1f: %.2fx; environment GPU bytes then: %llu\n",
                before.wall, without.w(), without.w() / before.wall, before.cpu, without.c(),
                without.c() / before.cpu, static_cast<unsigned long long>(bytes_after));
    return 0;
}
