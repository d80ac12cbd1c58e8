// sherpa-bench-pathtrace [--rounds N] [--frames N] [--width W --height H] [--max-bounces N]
//                        [--no-bc] [SCENE]
// The path tracer's cost per sample (render --renderer rt --view lit, one sample per
// frame) next to references measured in the same run on the same device, interleaved
// in rounds so that a shared machine's load falls on all alike: the raster lit frame
// of the same scene and size, and the path tracer at one bounce (direct light only).
// Per column the median over the frames of the GPU time (timestamps) and the mean
// process CPU time per frame (lavapipe's threads included: on a CPU device it moves
// less with the machine's load than wall time does). Default: DamagedHelmet at
// 320x240, the room environment and the default sun, as docs/path_tracer.md "Speed".
// Ends with the estimated error of the accumulated image (path_trace_error).
#include "process_cpu.h"

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace sherpa;

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Column {
    Column(const char* n, const render::FrameRequest& r) : name(n), request(r) {}
    const char* name;
    render::FrameRequest request;
    std::vector<double> gpu_ms;
    double cpu_ms = 0.0;
    int frames = 0;
};

void run(render::Renderer& renderer, Column& c, int frames) {
    const double cpu0 = bench::process_cpu_ms();
    for (int f = 0; f < frames; ++f) c.gpu_ms.push_back(renderer.render(c.request).gpu_ms);
    c.cpu_ms += bench::process_cpu_ms() - cpu0;
    c.frames += frames;
}

} // namespace

int main(int argc, char** argv) {
    sherpa::core::keep_freed_memory_mapped(); // as sherpa-cli: lavapipe's blocks stay mapped
    int rounds = 4, frames = 4;
    std::uint32_t bounces = 8;
    bool no_bc = false;
    render::FrameRequest base;
    base.width = 320;
    base.height = 240;
    std::string spec =
        (fs::path(SHERPA_ASSETS_DIR) / "gltf/DamagedHelmet/glTF/DamagedHelmet.gltf").string();
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc)
            rounds = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--width") && i + 1 < argc)
            base.width = std::uint32_t(std::max(1, std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--height") && i + 1 < argc)
            base.height = std::uint32_t(std::max(1, std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--max-bounces") && i + 1 < argc)
            bounces = std::uint32_t(std::max(0, std::atoi(argv[++i])));
        else if (!std::strcmp(argv[i], "--no-bc"))
            no_bc = true;
        else if (argv[i][0] == '-') {
            std::fprintf(stderr, "usage: sherpa-bench-pathtrace [--rounds N] [--frames N] "
                                 "[--width W --height H] [--max-bounces N] [--no-bc] [SCENE]\n");
            return 2;
        } else
            spec = argv[i];
    }

    gpu::ContextOptions options;
    options.validation = false; // the layer's CPU cost would distort the times
    gpu::Context context(options);
    render::RendererOptions renderer_options;
    renderer_options.ray_tracing = true;
    renderer_options.textures.cache_dir = tex::default_cache_dir_from_environment();
    renderer_options.textures.force_rgba8 = no_bc;
    render::Renderer renderer(context, renderer_options);
    const render::EnvironmentImage room = render::room_environment();
    renderer.set_environment(&room);
    scene::LoadResult r = scene::load_scene(spec);
    if (!r) {
        std::fprintf(stderr, "error: %s\n", r.error.c_str());
        return 1;
    }
    renderer.load(*r.scene);
    // The camera sherpa-cli render's `--camera auto` makes: the scene framed at this aspect.
    scene::FramingOptions framing;
    framing.fov_y_degrees = base.camera.fov_degrees;
    framing.aspect = float(base.width) / float(base.height);
    base.camera = render::explicit_camera(scene::frame_scene(*r.scene, nullptr, framing));

    Column raster{"raster lit", base};
    Column path{"path traced", base};
    path.request.renderer = render::RendererKind::RayTraced;
    path.request.path.samples = 1;
    path.request.path.max_bounces = bounces;
    Column direct{"path, 1 bounce", path.request};
    direct.request.path.max_bounces = 1;
    // Pipelines, shadow maps and first launches are not counted.
    for (Column* c : {&raster, &path, &direct}) renderer.render(c->request);
    for (int round = 0; round < rounds; ++round)
        for (Column* c : {&raster, &path, &direct}) run(renderer, *c, frames);

    std::printf("device: %s; %s at %ux%u, %d rounds of %d frames (1 sample each)\n",
                context.info().name.c_str(), fs::path(spec).stem().string().c_str(), base.width,
                base.height, rounds, frames);
    std::printf("%-16s %12s %12s %14s %14s\n", "", "GPU ms", "CPU ms", "GPU / raster",
                "CPU / raster");
    const double raster_gpu = median(raster.gpu_ms), raster_cpu = raster.cpu_ms / raster.frames;
    for (Column* c : {&raster, &path, &direct}) {
        const double g = median(c->gpu_ms), cpu = c->cpu_ms / c->frames;
        std::printf("%-16s %12.2f %12.2f %14.2f %14.2f\n", c->name, g, cpu, g / raster_gpu,
                    cpu / raster_cpu);
    }
    std::printf("path / 1 bounce: GPU %.3f, CPU %.3f\n",
                median(path.gpu_ms) / median(direct.gpu_ms),
                (path.cpu_ms / path.frames) / (direct.cpu_ms / direct.frames));
    // The last column rendered was `direct`: the full path tracer's error needs its own
    // accumulation, redone here at the sample count measured.
    render::FrameRequest again = path.request;
    again.path.samples = std::uint32_t(std::min(path.frames, 64));
    again.path.restart = true;
    renderer.render(again);
    const render::PathTraceError e = render::path_trace_error(renderer);
    std::printf("estimated error at %u spp: %.3f%% (mean standard error %.5f of mean luminance "
                "%.5f)\n",
                e.samples, 100.0 * e.relative_error, e.mean_standard_error, e.mean_luminance);
    return 0;
}
