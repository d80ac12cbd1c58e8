// sherpa-bench-render [--frames N] [--width W --height H] [--csv] [SCENE...]
// Per scene: median frame time of the full renderer (lit view, all passes) next to
// a floor measured in the same run on the same device: the same triangles drawn
// with positions only and a constant colour. Also the lit frame with the shadow
// cascades re-rendered every frame (normally they are cached while camera, light
// and scene stay unchanged). Frame time = submit to completion, wall clock; the
// first two frames (pipeline compilation, first shadow map) are not counted.
#include <sherpa/gpu/renderer.h>
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

double median_frame_ms(gpu::Renderer& renderer, const gpu::RenderSettings& s, int frames) {
    std::vector<double> ms;
    for (int f = 0; f < frames + 2; ++f) {
        const auto t0 = std::chrono::steady_clock::now();
        renderer.render(s);
        const double dt =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        if (f >= 2) ms.push_back(dt);
    }
    return median(ms);
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
    int frames = 20;
    bool csv = false;
    gpu::RenderSettings lit;
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
        else
            scenes.push_back(argv[i]);
    }
    if (scenes.empty()) scenes = default_scenes();

    gpu::ContextOptions options;
    options.validation = false; // the layer's CPU cost would distort frame times
    gpu::Context context(options);
    gpu::Renderer renderer(context);
    std::printf("device: %s, %ux%u, median of %d frames\n", context.info().name.c_str(), lit.width,
                lit.height, frames);
    if (csv)
        std::printf("scene,triangles,floor_ms,lit_ms,ratio,lit_fps,lit_shadows_each_frame_ms\n");
    else
        std::printf("%-26s %9s %9s %9s %7s %8s %14s\n", "scene", "triangles", "floor ms", "lit ms",
                    "ratio", "lit fps", "lit+shadow ms");
    for (const std::string& spec : scenes) {
        LoadResult r = load_scene(spec);
        if (!r) {
            std::fprintf(stderr, "error: %s\n", r.error.c_str());
            continue;
        }
        renderer.load(*r.scene);
        gpu::RenderSettings floor = lit;
        floor.floor_only = true;
        gpu::RenderSettings uncached = lit;
        uncached.cache_shadows = false;
        const double floor_ms = median_frame_ms(renderer, floor, frames);
        const double lit_ms = median_frame_ms(renderer, lit, frames);
        const double shadow_ms = median_frame_ms(renderer, uncached, frames);
        const std::string name =
            spec.rfind("builtin:", 0) == 0 ? spec : fs::path(spec).stem().string();
        const auto tris = static_cast<unsigned long long>(renderer.scene()->triangle_count());
        if (csv)
            std::printf("%s,%llu,%.2f,%.2f,%.2f,%.1f,%.2f\n", name.c_str(), tris, floor_ms, lit_ms,
                        lit_ms / floor_ms, 1000.0 / lit_ms, shadow_ms);
        else
            std::printf("%-26s %9llu %9.2f %9.2f %7.2f %8.1f %14.2f\n", name.c_str(), tris,
                        floor_ms, lit_ms, lit_ms / floor_ms, 1000.0 / lit_ms, shadow_ms);
        std::fflush(stdout);
        renderer.unload();
    }
    return 0;
}
