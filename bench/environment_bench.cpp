// sherpa-bench-environment [--frames N] [--repeats N] [--width W --height H]
//                           [--irradiance cube|sh9] [--prefilter-only] [--anisotropy]
//                           [SCENE]
// Environment lighting on this device (lavapipe here), same-run ratios:
//  1. Prefiltering a 1024x512 EXR (Blender's studio lights, else the room at 1024x512):
//     upload + every compute pass, wall clock and process CPU time (lavapipe's
//     threads included: on a shared machine it moves less than wall time), per pass
//     by GPU timestamps; the first environment (which also makes the BRDF lookup
//     table) and a switch to another, in turn. Goal: under 300 ms.
//  2. SCENE (default DamagedHelmet) lit at W x H (default 1280x720): the frame with the
//     environment (room) next to the frame without (the ambient term), and with the
//     environment behind a solid background (its lighting alone); two renderers drawn
//     in turn, one frame each, for frames x repeats rounds. Goal: at most 1.3x. The
//     view holds still, as in an inspector between camera moves (the background is
//     kept then); then the same with the camera orbiting 2 degrees a frame (drawn each
//     frame), with the environment and behind a solid background (its lighting alone),
//     so that the background pass's share of a moving view is the difference.
//  3. No environment pays nothing: the frame of a renderer whose environment was
//     removed next to one that never had one, and the environment's GPU bytes then (0).
// With --anisotropy instead: KHR_materials_anisotropy's environment modes
// (AnisotropyLighting) on SCENE (e.g. tests/data/material_sweeps/anisotropy_sweep.gltf)
// lit by the room: one renderer draws isotropic, albedo and lobe in turn, one frame
// each, and each round's ratios to isotropic are taken; and the anisotropic lookup
// table's bytes and build.
#include "process_cpu.h"

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/scene_loader.h>

#include <glm/gtc/matrix_transform.hpp>

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

// One frame's wall time and process CPU time (every lavapipe thread): on a shared
// machine the CPU time moves far less with other work than the wall time.
struct FrameTime {
    double wall = 0.0, cpu = 0.0;
};

FrameTime frame_ms(render::Renderer& r, const render::FrameRequest& s) {
    const double t0 = now_ms(), c0 = bench::process_cpu_ms();
    r.render(s);
    return {now_ms() - t0, bench::process_cpu_ms() - c0};
}

struct Runs {
    std::vector<double> wall, cpu;
    void add(FrameTime t) { wall.push_back(t.wall), cpu.push_back(t.cpu); }
    double w() const { return median(wall); }
    double c() const { return median(cpu); }
};

// Frames of two renderers drawn next to each other, and each pair's ratios.
struct Pairs {
    Runs a, b;
    std::vector<double> ratio, ratio_cpu;
    void add(FrameTime x, FrameTime y) {
        a.add(x), b.add(y);
        ratio.push_back(x.wall / y.wall), ratio_cpu.push_back(x.cpu / y.cpu);
    }
};

// --anisotropy: the modes' frames in turn (see the top).
int anisotropy_modes(gpu::Context& context, const std::string& scene_spec,
                     const render::FrameRequest& s, int rounds) {
    scene::LoadResult loaded = scene::load_scene(scene_spec);
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return 1;
    }
    render::Renderer r(context);
    const render::EnvironmentImage room = render::room_environment();
    r.set_environment(&room);
    r.load(*loaded.scene);
    const render::EnvironmentStats env = r.resident().environment;
    std::printf("%s: anisotropic table %llu bytes, built in %.2f GPU ms\n", scene_spec.c_str(),
                static_cast<unsigned long long>(env.anisotropy_lut_bytes),
                env.anisotropy_lut_gpu_ms);
    using render::AnisotropyLighting;
    const AnisotropyLighting modes[] = {AnisotropyLighting::Isotropic, AnisotropyLighting::Albedo,
                                        AnisotropyLighting::Lobe};
    render::FrameRequest m[3];
    Pairs pairs[2]; // albedo, lobe against isotropic
    for (int k = 0; k < 3; ++k) {
        m[k] = s;
        m[k].anisotropy_lighting = modes[k];
        r.render(m[k]); // warm: pipelines
    }
    for (int i = 0; i < rounds; ++i) {
        const FrameTime iso = frame_ms(r, m[0]);
        pairs[0].add(frame_ms(r, m[1]), iso);
        pairs[1].add(frame_ms(r, m[2]), iso);
    }
    std::printf("lit %ux%u, %d rounds (median wall ms; CPU ms; ratio: median of the rounds'):\n",
                s.width, s.height, rounds);
    std::printf("  isotropic %.1f (CPU %.1f)\n", pairs[0].b.w(), pairs[0].b.c());
    for (int k = 0; k < 2; ++k)
        std::printf("  %s %.1f: %.3fx; CPU %.1f: %.3fx\n", k == 0 ? "albedo" : "lobe",
                    pairs[k].a.w(), median(pairs[k].ratio), pairs[k].a.c(),
                    median(pairs[k].ratio_cpu));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    core::keep_freed_memory_mapped();
    int frames = 5, repeats = 5;
    bool prefilter_only = false, anisotropy = false;
    render::EnvironmentOptions options;
    render::FrameRequest s;
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
        else if (a == "--irradiance" && i + 1 < argc)
            options.irradiance = std::string(argv[++i]) == "sh9" ? render::IrradianceMode::Sh9
                                                                 : render::IrradianceMode::Cube;
        else if (a == "--prefilter-only")
            prefilter_only = true;
        else if (a == "--anisotropy")
            anisotropy = true;
        else if (!a.empty() && a[0] != '-')
            scene_spec = a;
        else {
            std::fprintf(stderr,
                         "usage: sherpa-bench-environment [--frames N] [--repeats N] "
                         "[--width W --height H] [--irradiance cube|sh9] [--prefilter-only] "
                         "[--anisotropy] [SCENE]\n");
            return 2;
        }
    }
    gpu::Context context;
    render::Renderer renderer(context);
    std::printf("device: %s\n", context.info().name.c_str());
    if (anisotropy) return anisotropy_modes(context, scene_spec, s, frames * repeats);

    // 1. Prefilter.
    const auto lights = render::installed_studio_lights();
    render::EnvironmentImage image;
    const auto studio = std::find_if(lights.begin(), lights.end(), [](const std::string& f) {
        return f.size() >= 10 && f.compare(f.size() - 10, 10, "studio.exr") == 0;
    });
    image = studio != lights.end() ? render::load_environment(*studio).image
                                   : render::room_environment(1024);
    std::printf("prefilter %s (%ux%u), %d runs of each, in turn:\n", image.name.c_str(),
                image.width, image.height, repeats);
    // The first environment after none also makes the split-sum lookup table (the
    // BRDF's, kept while environments follow each other); a switch to another reuses it.
    struct Series {
        std::vector<double> wall, cpu, gpu_ms, pass[5];
        void add(const render::EnvironmentStats& st, double cpu_ms) {
            wall.push_back(st.prefilter_ms), cpu.push_back(cpu_ms), gpu_ms.push_back(st.gpu_ms);
            for (int p = 0; p < 5; ++p) pass[p].push_back(st.pass_ms[p]);
        }
        void print(const char* what) const {
            std::printf("  %s: median wall %.1f ms, CPU %.1f ms (all threads), GPU passes %.1f ms "
                        "[radiance cube %.1f, GGX %.1f, irradiance %.1f, Charlie %.1f, LUT %.1f]\n",
                        what, median(wall), median(cpu), median(gpu_ms), median(pass[0]),
                        median(pass[1]), median(pass[2]), median(pass[3]), median(pass[4]));
        }
    } first, next;
    for (int i = 0; i < repeats; ++i) {
        renderer.set_environment(nullptr);
        for (Series* series : {&first, &next}) {
            const double c0 = bench::process_cpu_ms();
            renderer.set_environment(&image, options);
            series->add(renderer.resident().environment, bench::process_cpu_ms() - c0);
        }
    }
    renderer.set_environment(nullptr);
    first.print("first (with the lookup table)");
    next.print("next (another environment)");
    std::printf("  goal < 300 ms: %s (wall, first)\n",
                median(first.wall) < 300.0 ? "met" : "NOT met");

    if (prefilter_only) return 0;

    // 2. and 3. Frames: two renderers over the same scene, one with the environment and
    // one that never had one, drawn in turn frame by frame (with, with a solid
    // background, without), so that machine load hits the three alike; each round's
    // ratio pairs frames drawn next to each other.
    scene::LoadResult loaded = scene::load_scene(scene_spec);
    if (!loaded) {
        std::fprintf(stderr, "error: %s\n", loaded.error.c_str());
        return 1;
    }
    render::Renderer plain(context);
    renderer.load(*loaded.scene);
    plain.load(*loaded.scene);
    const render::EnvironmentImage room = render::room_environment();
    renderer.set_environment(&room, options);
    render::FrameRequest solid = s;
    solid.background = render::Background::Color;
    const int rounds = frames * repeats;
    Runs with, with_solid, without;
    std::vector<double> ratio, ratio_cpu, ratio_solid, ratio_solid_cpu;
    for (render::Renderer* r : {&renderer, &plain}) r->render(s), r->render(solid); // warm
    for (int i = 0; i < rounds; ++i) {
        const FrameTime a = frame_ms(renderer, s);
        const FrameTime b = frame_ms(renderer, solid);
        const FrameTime c = frame_ms(plain, s);
        with.add(a), with_solid.add(b), without.add(c);
        ratio.push_back(a.wall / c.wall), ratio_cpu.push_back(a.cpu / c.cpu);
        ratio_solid.push_back(b.wall / c.wall), ratio_solid_cpu.push_back(b.cpu / c.cpu);
    }
    std::printf("%s lit %ux%u, %d rounds of one frame each (median wall ms; CPU ms; ratio: "
                "median of the rounds' ratios):\n",
                scene_spec.c_str(), s.width, s.height, rounds);
    std::printf("  with the environment %.1f, without %.1f: %.2fx; CPU %.1f / %.1f: %.2fx "
                "(goal <= 1.3x)\n",
                with.w(), without.w(), median(ratio), with.c(), without.c(), median(ratio_cpu));
    std::printf("  with the environment but a solid background (lighting alone) %.1f: %.2fx; "
                "CPU %.1f: %.2fx\n",
                with_solid.w(), median(ratio_solid), with_solid.c(), median(ratio_solid_cpu));
    // 2b. A moving view: the camera orbits 2 degrees a frame about the framed model, so
    // no two frames of the environment's renderer share a view (the background is
    // drawn each frame, never kept).
    {
        const render::CameraView framed =
            render::resolve_camera(s.camera, *loaded.scene, float(s.width) / float(s.height));
        const glm::mat4 to_world = glm::inverse(framed.view);
        const glm::vec3 forward = -glm::vec3(to_world[2]);
        const glm::vec3 centre = framed.position + forward * glm::length(framed.position);
        Pairs moving, moving_solid;
        for (int i = 0; i < rounds; ++i) {
            const float yaw = glm::radians(2.0f * float(i + 1));
            render::FrameRequest m = s;
            m.camera.kind = render::CameraSpec::Kind::Explicit;
            m.camera.eye = centre + glm::vec3(glm::rotate(glm::mat4(1.0f), yaw, {0, 1, 0}) *
                                              glm::vec4(framed.position - centre, 0.0f));
            m.camera.target = centre;
            m.camera.fov_degrees = glm::degrees(framed.fov_y);
            render::FrameRequest m_solid = m;
            m_solid.background = render::Background::Color;
            const FrameTime a = frame_ms(renderer, m);
            const FrameTime a_solid = frame_ms(renderer, m_solid);
            const FrameTime b = frame_ms(plain, m);
            moving.add(a, b), moving_solid.add(a_solid, b);
        }
        std::printf("  a moving view (2 degrees a frame), with the environment %.1f, without "
                    "%.1f: %.2fx; CPU %.1f / %.1f: %.2fx\n",
                    moving.a.w(), moving.b.w(), median(moving.ratio), moving.a.c(), moving.b.c(),
                    median(moving.ratio_cpu));
        // The same frames behind a solid background: the moving view's lighting alone, so
        // that what the background pass adds while the view moves is the difference.
        std::printf("  the moving view with a solid background (lighting alone) %.1f: %.2fx; "
                    "CPU %.1f: %.2fx\n",
                    moving_solid.a.w(), median(moving_solid.ratio), moving_solid.a.c(),
                    median(moving_solid.ratio_cpu));
    }
    // 3. The environment removed: the frame against the renderer that never had one.
    renderer.set_environment(nullptr);
    renderer.render(s);
    Pairs removed; // after one was removed, never made
    for (int i = 0; i < rounds; ++i) {
        const FrameTime a = frame_ms(renderer, s);
        removed.add(a, frame_ms(plain, s));
    }
    std::printf("  no environment: after one was removed %.1f, never made %.1f: %.2fx; CPU "
                "%.1f / %.1f: %.2fx; environment GPU bytes then: %llu\n",
                removed.a.w(), removed.b.w(), median(removed.ratio), removed.a.c(), removed.b.c(),
                median(removed.ratio_cpu),
                static_cast<unsigned long long>(renderer.resident().environment.bytes));
    return 0;
}
