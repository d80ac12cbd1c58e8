// sherpa-bench-cull [--csv FILE] [--sizes 10000,100000,1000000] [--repeat N]
// Per builtin:grid size and method: ns per object (median over repeats, one core)
// and false positives against the exact test, next to a memory-read floor measured
// in the same run (reading the six box arrays and writing one byte per box, with
// the widest SIMD available), and the full camera pass (cull + draw groups).
#include <sherpa/gpu/context.h>
#include <sherpa/render/gpu_culling.h>
#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <immintrin.h>
#include <memory>
#include <string>
#include <vector>

using namespace sherpa;

namespace {

using Clock = std::chrono::steady_clock;

double median_ns_per_object(int repeat, std::size_t n, const std::function<void()>& body) {
    std::vector<double> t;
    body(); // warm caches and page in outputs
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        body();
        t.push_back(std::chrono::duration<double, std::nano>(Clock::now() - t0).count() /
                    static_cast<double>(n));
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// The floor: touch every byte the p-vertex kernel reads and write what it writes.
__attribute__((target("avx512f,avx512bw,avx512vl"))) void
read_floor_avx512(const scene::BoxesSoA& b, std::uint8_t* out) {
    const std::size_t n = b.size();
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        __m512 s = _mm512_add_ps(_mm512_loadu_ps(&b.min_x[i]), _mm512_loadu_ps(&b.min_y[i]));
        s = _mm512_add_ps(s, _mm512_loadu_ps(&b.min_z[i]));
        s = _mm512_add_ps(s, _mm512_loadu_ps(&b.max_x[i]));
        s = _mm512_add_ps(s, _mm512_loadu_ps(&b.max_y[i]));
        s = _mm512_add_ps(s, _mm512_loadu_ps(&b.max_z[i]));
        const __mmask16 m = _mm512_cmp_ps_mask(s, _mm512_setzero_ps(), _CMP_GE_OQ);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm_maskz_set1_epi8(m, 1));
    }
    for (; i < n; ++i)
        out[i] =
            b.min_x[i] + b.min_y[i] + b.min_z[i] + b.max_x[i] + b.max_y[i] + b.max_z[i] >= 0.0f;
}

std::int64_t false_positives(const std::vector<std::uint8_t>& v,
                             const std::vector<std::uint8_t>& exact) {
    std::int64_t fp = 0;
    for (std::size_t i = 0; i < v.size(); ++i) fp += (v[i] && !exact[i]) ? 1 : 0;
    return fp;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::uint64_t> sizes = {10000, 100000, 1000000};
    int repeat = 21;
    const char* csv_path = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--csv") && i + 1 < argc)
            csv_path = argv[++i];
        else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
            sizes.clear();
            for (char* tok = std::strtok(argv[++i], ","); tok; tok = std::strtok(nullptr, ","))
                sizes.push_back(std::strtoull(tok, nullptr, 10));
        } else {
            std::fprintf(stderr,
                         "usage: sherpa-bench-cull [--csv FILE] [--sizes N,N,..] [--repeat N]\n");
            return 2;
        }
    }
    const core::SimdLevel best = core::best_simd_level();
    // The GPU path on whatever device the engine picks (lavapipe by default,
    // SHERPA_DEVICE=NVIDIA for a discrete GPU).
    std::unique_ptr<gpu::Context> gpu_context;
    std::unique_ptr<gpu::ResourceManager> gpu_resources;
    std::unique_ptr<render::GpuCuller> gpu_culler;
    std::string gpu_name = "gpu";
    try {
        gpu::ContextOptions copt;
        copt.validation = false;
        gpu_context = std::make_unique<gpu::Context>(copt);
        gpu_resources = std::make_unique<gpu::ResourceManager>(*gpu_context);
        gpu_culler = std::make_unique<render::GpuCuller>(*gpu_context, *gpu_resources);
        gpu_name = "gpu pvertex";
        std::printf("GPU: %s\n", gpu_context->info().name.c_str());
    } catch (const std::exception& e) {
        std::printf("GPU path skipped: %s\n", e.what());
    }
    std::FILE* csv = csv_path ? std::fopen(csv_path, "w") : nullptr;
    if (csv) std::fprintf(csv, "instances,method,ns_per_object,false_positives,visible\n");
    std::printf("best SIMD level: %s; one thread\n", std::string(to_string(best)).c_str());
    std::printf("%10s %-18s %12s %14s %10s %10s\n", "instances", "method", "ns/object",
                "false pos.", "visible", "x floor");
    for (std::uint64_t n : sizes) {
        const scene::LoadResult r = scene::load_scene("builtin:grid?n=" + std::to_string(n));
        if (!r) {
            std::fprintf(stderr, "error: %s\n", r.error.c_str());
            return 1;
        }
        const scene::CullInput input = scene::prepare_cull_input(*r.scene);
        // A camera in the middle of the grid, 8 units up, looking along +X and a
        // little down: about a quarter of the grid is in view, and many boxes
        // straddle the side planes.
        scene::CameraSpec cam;
        cam.eye = {0.0f, 8.0f, 0.0f};
        cam.target = {1.0f, 7.8f, 0.35f};
        cam.fov_y_degrees = 50.0f;
        const scene::Frustum f = scene::frustum_from_view_projection(cam.view_projection());
        std::vector<std::uint8_t> out(n), exact(n);
        scene::cull_boxes(f, input.boxes, scene::CullMethod::Exact, best, exact);
        const double floor_ns =
            median_ns_per_object(repeat, n, [&] { read_floor_avx512(input.boxes, out.data()); });
        auto row = [&](const char* name, double ns, std::int64_t fp, std::uint64_t visible) {
            std::printf("%10llu %-18s %12.3f %14lld %10llu %10.2f\n", (unsigned long long)n, name,
                        ns, (long long)fp, (unsigned long long)visible, ns / floor_ns);
            if (csv)
                std::fprintf(csv, "%llu,%s,%.4f,%lld,%llu\n", (unsigned long long)n, name, ns,
                             (long long)fp, (unsigned long long)visible);
        };
        row("read floor", floor_ns, -1, 0);
        struct Variant {
            const char* name;
            scene::CullMethod method;
            core::SimdLevel simd;
        };
        const Variant variants[] = {
            {"sphere", scene::CullMethod::Sphere, core::SimdLevel::Scalar},
            {"pvertex scalar", scene::CullMethod::PVertex, core::SimdLevel::Scalar},
            {"pvertex avx2", scene::CullMethod::PVertex, core::SimdLevel::Avx2},
            {"pvertex avx512", scene::CullMethod::PVertex, core::SimdLevel::Avx512},
            {"exact", scene::CullMethod::Exact, best}};
        for (const Variant& v : variants) {
            if (v.simd > best) continue;
            const double ns = median_ns_per_object(
                repeat, n, [&] { scene::cull_boxes(f, input.boxes, v.method, v.simd, out); });
            std::uint64_t visible = 0;
            for (std::uint8_t x : out) visible += x;
            row(v.name, ns, false_positives(out, exact), visible);
        }
        {
            // The kernels stop testing planes once a whole SIMD block is outside, so
            // the view above favours them; from high above, every box is in view and
            // each block runs every plane: the worst case for the fastest path.
            scene::CameraSpec above;
            above.eye = {0.0f, 4.0f * std::sqrt(static_cast<float>(n)), 0.0f};
            above.target = {0.0f, 0.0f, -0.01f};
            above.fov_y_degrees = 90.0f;
            above.aspect = 1.0f;
            const scene::Frustum all = scene::frustum_from_view_projection(above.view_projection());
            const double ns = median_ns_per_object(repeat, n, [&] {
                scene::cull_boxes(all, input.boxes, scene::CullMethod::PVertex, best, out);
            });
            std::uint64_t visible = 0;
            for (std::uint8_t x : out) visible += x;
            row(best == core::SimdLevel::Avx512 ? "pvertex avx512 all"
                : best == core::SimdLevel::Avx2 ? "pvertex avx2 all"
                                                : "pvertex scalar all",
                ns, -1, visible);
        }
        if (gpu_culler) {
            // GPU-driven path: compute dispatch time from timestamps, median of runs.
            const scene::ScenePasses passes = scene::build_mesh_passes(*r.scene);
            gpu_culler->build(passes.forward, *r.scene);
            std::vector<double> ms;
            render::GpuCullReadback rb;
            for (int k = 0; k < std::max(3, repeat / 3); ++k) {
                rb = gpu_culler->run(f, scene::CullMethod::PVertex);
                ms.push_back(rb.gpu_ms);
            }
            std::sort(ms.begin(), ms.end());
            std::vector<std::uint8_t> by_instance(n, 0);
            for (std::size_t k = 0; k < rb.visible.size(); ++k)
                by_instance[gpu_culler->object_instances()[k]] = rb.visible[k];
            std::uint64_t visible = 0;
            for (std::uint8_t x : by_instance) visible += x;
            row(gpu_name.c_str(), ms[ms.size() / 2] * 1e6 / static_cast<double>(n),
                false_positives(by_instance, exact), visible);
        }
        scene::CullOptions opt;
        opt.simd = best;
        const double pass_ns = median_ns_per_object(
            repeat, n, [&] { scene::cull_pass(input, f, cam.eye, opt, "camera"); });
        row("pass (cull+groups)", pass_ns, -1, 0); // p-vertex pass; see its row for false positives
        std::printf("%10s full camera pass: %.3f ms\n", "",
                    pass_ns * static_cast<double>(n) * 1e-6);
    }
    if (csv) std::fclose(csv);
    gpu_culler.reset();
    if (gpu_resources) gpu_resources->flush();
    gpu_resources.reset();
    return 0;
}
