// The lighting family: the raster's lighting approximations against the converged
// path-traced image of the scene (lab/families.h, lighting_plan.h).
#include <sherpa/gpu/context.h>
#include <sherpa/lab/families.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/framing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <tuple>

#include "lab_gpu.h"
#include "lighting_images.h"
#include "lighting_plan.h"

namespace sherpa::lab {
namespace {

using detail::LightingGroup;
using detail::LightingMethod;
using detail::LightingSetup;

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

bool has_transmission(const scene::Scene& scene) {
    for (const scene::MaterialInstance& m : scene.materials)
        if (m.transmission && m.transmission->factor > 0.0f) return true;
    return false;
}

bool has_anisotropy(const scene::Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const scene::MaterialInstance& m) { return m.anisotropy.has_value(); });
}

// The sun whose cascades the raster draws: the scene's first directional light, else
// the default sun where the scene has no lights and it is on (frame_data.cpp's rule).
bool has_shadowing_sun(const scene::Scene& scene, const render::FrameRequest& view) {
    for (const scene::PlacedLight& pl : scene.placed_lights)
        if (pl.light < scene.lights.size() &&
            scene.lights[pl.light].type == scene::LightType::Directional)
            return true;
    return scene.placed_lights.empty() && view.sun;
}

// Why a group cannot be measured on this scene (empty: it can).
std::string not_applicable(LightingGroup g, const scene::Scene& scene,
                           const LightingFamilyOptions& o) {
    const bool environment = o.lighting.environment != nullptr;
    switch (g) {
    case LightingGroup::Irradiance:
    case LightingGroup::Prefilter:
    case LightingGroup::Compensation:
        return environment ? ""
                           : "not applicable: no environment (the sky/ground ambient "
                             "term lights the scene; nothing to prefilter)";
    case LightingGroup::Anisotropy:
        return !environment            ? "not applicable: no environment"
               : has_anisotropy(scene) ? ""
                                       : "not applicable: no material has KHR_materials_anisotropy";
    case LightingGroup::Shadows:
        return has_shadowing_sun(scene, o.lighting.settings)
                   ? ""
                   : "not applicable: no directional light casts shadow maps (the scene's "
                     "lights have none and the default sun is off or replaced by them)";
    case LightingGroup::Transmission:
        return has_transmission(scene) ? ""
                                       : "not applicable: no material has "
                                         "KHR_materials_transmission with a factor above 0";
    case LightingGroup::PathTracer:
        return "";
    }
    return "";
}

scene::Scene without_transmission(const scene::Scene& scene) {
    scene::Scene copy = scene;
    for (scene::MaterialInstance& m : copy.materials) m.transmission.reset();
    return copy;
}

// The figures of an image against the reference, per material after the whole image.
void set_errors(MethodResult& r, const detail::ImageDifference& d) {
    r.errors = {{"mean_diff", d.mean},
                {"psnr_db", std::isfinite(d.psnr_db) ? d.psnr_db : 999.0, true}};
    for (std::size_t m = 0; m < d.material_pixels.size(); ++m)
        if (d.material_pixels[m] > 0)
            r.errors.push_back(
                {"material_" + std::to_string(m) + "_mean_diff", d.material_mean[m]});
}

class LightingFamily final : public Family {
public:
    explicit LightingFamily(LightingFamilyOptions options) : options_(std::move(options)) {}
    std::string_view name() const override { return "lighting"; }

    std::vector<MethodInfo> methods() const override {
        std::vector<MethodInfo> out;
        for (const LightingMethod& m : detail::lighting_methods(options_)) out.push_back(m.info);
        return out;
    }

    FamilyReport run(const scene::Scene& scene, const RunControl& control) const override;

private:
    struct Frame {
        std::vector<std::uint8_t> rgba;
        double ms = 0.0;
        bool timed = false;
        render::EnvironmentStats environment;
        std::vector<Failure> failures;
    };
    // A raster renderer for the setups of one shadow resolution, with the environment
    // and scene of the last setup drawn.
    struct Raster {
        std::unique_ptr<render::Renderer> renderer;
        std::uint32_t shadow_resolution = 0;
        std::optional<std::string> environment; // key of its EnvironmentOptions
        int transmission = -1;
    };

    render::FrameRequest view_settings(const scene::CameraSpec& camera) const {
        render::FrameRequest s;
        render::copy_lighting(options_.lighting.settings, s);
        s.width = options_.width;
        s.height = options_.height;
        s.camera = render::explicit_camera(camera);
        s.path.max_bounces = options_.max_bounces;
        return s;
    }

    Frame draw(gpu::Context& context, Raster& raster, const scene::Scene& scene,
               const scene::Scene& stripped, const LightingSetup& setup,
               const render::FrameRequest& view) const;
    void reference(gpu::Context& context, const scene::Scene& scene,
                   const render::FrameRequest& view, const std::vector<std::int32_t>& ids,
                   FamilyReport& report, const std::vector<LightingMethod>& plan,
                   detail::Progress& progress, std::vector<std::uint8_t>& rgba) const;

    LightingFamilyOptions options_;
};

LightingFamily::Frame LightingFamily::draw(gpu::Context& context, Raster& raster,
                                           const scene::Scene& scene, const scene::Scene& stripped,
                                           const LightingSetup& setup,
                                           const render::FrameRequest& view) const {
    Frame f;
    const std::size_t seen = context.validation().count();
    const std::string env_key = setup.environment_key();
    if (!raster.renderer || raster.shadow_resolution != setup.shadow_resolution) {
        render::RendererOptions ro;
        ro.shadow_resolution = setup.shadow_resolution;
        raster.renderer.reset();
        raster.renderer = std::make_unique<render::Renderer>(context, ro);
        raster.shadow_resolution = setup.shadow_resolution;
        raster.environment.reset();
        raster.transmission = -1;
    }
    render::Renderer& r = *raster.renderer;
    if (raster.environment != env_key) {
        r.set_environment(options_.lighting.environment.get(), setup.environment);
        raster.environment = env_key;
    }
    if (raster.transmission != int(setup.transmission)) {
        r.load(setup.transmission ? scene : stripped);
        raster.transmission = int(setup.transmission);
    }
    render::FrameRequest s = view;
    s.shadows = setup.shadows;
    s.cascades = setup.cascades;
    s.shadow_pcf_taps = setup.taps;
    if (setup.compensation >= 0) s.energy_compensation = setup.compensation == 1;
    if (setup.anisotropy >= 0) s.anisotropy_lighting = render::AnisotropyLighting(setup.anisotropy);
    s.cache_shadows = false; // every frame pays for its cascades
    r.render(s, nullptr);    // pipelines made outside the timed frames
    std::vector<double> ms;
    for (std::uint32_t i = 0; i < std::max(options_.frames, 1u); ++i)
        ms.push_back(r.render(s, nullptr).gpu_ms);
    f.timed = context.info().timestamps;
    f.ms = detail::median(ms);
    // The compared image: supersampled, filtered down as the path tracer's box filter.
    const std::uint32_t k = std::max(options_.supersample, 1u);
    render::FrameRequest big = s;
    big.width *= k, big.height *= k;
    std::vector<std::uint8_t> rgba;
    r.render(big, &rgba);
    f.rgba = detail::downsample_srgb(rgba, s.width, s.height, k);
    f.environment = r.resident().environment;
    const auto& messages = context.validation().messages();
    for (std::size_t m = seen; m < messages.size(); ++m)
        f.failures.push_back({"validation message", messages[m].id_name, 1});
    return f;
}

void LightingFamily::reference(gpu::Context& context, const scene::Scene& scene,
                               const render::FrameRequest& view,
                               const std::vector<std::int32_t>& ids, FamilyReport& report,
                               const std::vector<LightingMethod>& plan, detail::Progress& progress,
                               std::vector<std::uint8_t>& rgba) const {
    render::RendererOptions ro;
    ro.ray_tracing = true;
    render::Renderer renderer(context, ro);
    renderer.set_environment(options_.lighting.environment.get());
    renderer.load(scene);
    report.warnings = renderer.resident().emissive.warnings; // the reference's light list
    const std::size_t seen = context.validation().count();
    auto step = [&] {
        progress.step();
        return !progress.stop();
    };
    const std::uint32_t spp = std::max(options_.reference_spp, 1u);
    std::vector<detail::PathImage> ref = detail::path_trace_series(renderer, view, 0, {spp}, step);
    if (ref.empty() || ref.back().spp != spp) return; // cancelled
    rgba = std::move(ref.back().rgba);
    const render::PathTraceError& e = ref.back().error;
    const std::vector<std::uint32_t> checkpoints = lighting_convergence_spp(options_);
    const std::vector<detail::PathImage> series =
        detail::path_trace_series(renderer, view, 1, checkpoints, step);
    if (series.size() != checkpoints.size()) return;
    std::vector<Failure> failures;
    const auto& messages = context.validation().messages();
    for (std::size_t m = seen; m < messages.size(); ++m)
        failures.push_back({"validation message", messages[m].id_name, 1});
    report.reference = "the path tracer (render --renderer rt --view lit) at " +
                       std::to_string(spp) + " spp, seed 0, " +
                       std::to_string(options_.max_bounces) + " bounces, " +
                       std::to_string(options_.width) + "x" + std::to_string(options_.height) +
                       ", the framed camera";
    report.notes.push_back(
        "reference: " + std::to_string(spp) + " spp in " + fixed(ref.back().gpu_ms, 0) +
        " GPU ms (" + fixed(ref.back().gpu_ms / spp, 1) + " ms per sample); its estimated error: " +
        fixed(100.0 * e.relative_error, 2) + "% of the mean luminance");
    for (std::size_t i = 0, k = 0; i < plan.size(); ++i) {
        if (plan[i].setup.group != LightingGroup::PathTracer) continue;
        const detail::PathImage& p = series[k++];
        MethodResult& r = report.methods[i];
        const detail::ImageDifference d =
            detail::image_difference(p.rgba, rgba, ids, scene.materials.size());
        r.ran = true;
        r.time = p.gpu_ms;
        r.total_ms = p.gpu_ms;
        set_errors(r, d);
        r.errors.push_back({"ms_per_sample", p.gpu_ms / std::max(p.spp, 1u)});
        if (p.spp > 1) // one sample has no variance: no estimate, not a zero
            r.errors.push_back({"estimated_error_percent", 100.0 * p.error.relative_error});
        r.failures = failures;
        r.note = "GPU ms of the accumulation up to " + std::to_string(p.spp) + " spp (seed 1)";
    }
    // Two independent images at n and N samples differ by sqrt(1/n + 1/N) of one
    // sample's noise: the last checkpoint's difference scaled to the reference's own.
    // The materials seen, with their pixels and (given a convergence image) their floor.
    // Without a convergence image the reference against itself: the materials' pixels.
    const detail::ImageDifference d = detail::image_difference(
        series.empty() ? rgba : series.back().rgba, rgba, ids, scene.materials.size());
    double scale = 0.0;
    if (!series.empty()) {
        const detail::PathImage& last = series.back();
        scale = std::sqrt((1.0 / spp) / (1.0 / last.spp + 1.0 / spp));
        report.notes.push_back(
            "noise floor: the reference is about " + fixed(d.mean * scale, 2) +
            " 8-bit steps (mean_diff) from its own converged image (the " +
            std::to_string(last.spp) + " spp image's " + fixed(d.mean, 2) +
            " scaled by sqrt(1/N / (1/n + 1/N))): differences below it are noise");
    }
    for (std::size_t m = 0; m < d.material_pixels.size(); ++m)
        if (d.material_pixels[m] > 0)
            report.notes.push_back(
                "material_" + std::to_string(m) + ": '" + scene.materials[m].name + "', " +
                std::to_string(d.material_pixels[m]) + " pixels" +
                (series.empty() ? "" : ", noise floor " + fixed(d.material_mean[m] * scale, 2)));
}

FamilyReport LightingFamily::run(const scene::Scene& scene, const RunControl& control) const {
    FamilyReport report;
    report.family = std::string(name());
    report.reference = "the path tracer's converged image (render --renderer rt --view lit)";
    report.time_unit = "ms/frame";
    report.chart_error = "mean_diff";
    std::vector<LightingMethod> plan = detail::lighting_methods(options_);
    // The view's compensation made explicit, so that "compensation on" (or off) is
    // known to draw the same frame as the other groups' default.
    for (LightingMethod& m : plan)
        if (m.setup.compensation < 0)
            m.setup.compensation = options_.lighting.settings.energy_compensation ? 1 : 0;
    for (const LightingMethod& m : plan) {
        MethodResult r;
        r.method = m.info;
        r.note = not_applicable(m.setup.group, scene, options_);
        report.methods.push_back(std::move(r));
    }
    const std::uint32_t spp = std::max(options_.reference_spp, 1u);
    const std::vector<std::uint32_t> checkpoints = lighting_convergence_spp(options_);
    // Launches of the path tracer (progress steps): at most kPathLaunch samples each, and
    // one more at each checkpoint that does not fall on a launch's end.
    const auto launches_to = [](std::uint32_t n) {
        return (n + detail::kPathLaunch - 1) / detail::kPathLaunch;
    };
    const std::size_t launches =
        launches_to(spp) +
        (checkpoints.empty() ? 0 : launches_to(checkpoints.back()) + checkpoints.size());
    detail::Progress progress(control, launches + plan.size());
    if (progress.stop()) return detail::cancelled_report(report.family);

    scene::FramingOptions framing;
    framing.aspect = float(options_.width) / float(std::max(options_.height, 1u));
    scene::CameraSpec camera = scene::frame_scene(scene, nullptr, framing);
    camera.aspect = framing.aspect;
    const render::FrameRequest view = view_settings(camera);
    report.notes.push_back(std::to_string(options_.width) + "x" + std::to_string(options_.height) +
                           ", the framed camera; time: GPU ms of the raster frame, median of " +
                           std::to_string(options_.frames) +
                           " (cascades redrawn each frame); the compared raster image drawn at " +
                           std::to_string(options_.supersample) +
                           "x the size and box-filtered down in linear values; mean_diff: mean "
                           "|raster - reference| in 8-bit display steps over the RGB of every "
                           "pixel");
    try {
        gpu::Context context(detail::family_context(options_.validation, options_.ray_tracing));
        if (!detail::ray_traces(context, report, progress, "no path-traced reference"))
            return report;
        const std::vector<std::int32_t> ids =
            detail::material_id_image(scene, camera, options_.width, options_.height);
        std::vector<std::uint8_t> truth;
        reference(context, scene, view, ids, report, plan, progress, truth);
        if (progress.stop()) return detail::cancelled_report(report.family);
        const scene::Scene stripped =
            has_transmission(scene) ? without_transmission(scene) : scene::Scene{};
        Raster raster;
        std::map<std::string, std::size_t> drawn; // setup key -> method measured with it
        // Setups of one shadow resolution together (each resolution is one renderer), and
        // within it of one environment (each is one prefilter) and one scene (one upload).
        std::vector<std::size_t> order(plan.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            const LightingSetup &x = plan[a].setup, &y = plan[b].setup;
            return std::tuple(x.shadow_resolution, x.environment_key(), !x.transmission) <
                   std::tuple(y.shadow_resolution, y.environment_key(), !y.transmission);
        });
        for (std::size_t i : order) {
            if (progress.stop()) return detail::cancelled_report(report.family);
            MethodResult& r = report.methods[i];
            const LightingSetup& setup = plan[i].setup;
            if (setup.group == LightingGroup::PathTracer || !r.note.empty() || truth.empty()) {
                progress.step();
                continue;
            }
            const std::string key = setup.key();
            if (const auto same = drawn.find(key); same != drawn.end()) {
                const MethodResult& twin = report.methods[same->second];
                r.ran = twin.ran, r.time = twin.time, r.total_ms = twin.total_ms;
                r.errors = twin.errors, r.failures = twin.failures;
                r.note = "the same frame as '" + twin.method.name + "'";
                progress.step();
                continue;
            }
            try {
                const double t0 = detail::process_cpu_ms();
                const Frame f = draw(context, raster, scene, stripped, setup, view);
                r.ran = true;
                r.time = f.ms;
                r.total_ms = detail::process_cpu_ms() - t0;
                set_errors(r, detail::image_difference(f.rgba, truth, ids, scene.materials.size()));
                if (setup.group == LightingGroup::Irradiance ||
                    setup.group == LightingGroup::Prefilter) {
                    r.errors.push_back({"environment_bytes", double(f.environment.bytes)});
                    r.errors.push_back({"prefilter_gpu_ms", f.environment.gpu_ms});
                }
                r.failures = f.failures;
                r.note = f.timed ? context.info().name
                                 : context.info().name + " (no timestamps: time 0)";
                drawn.emplace(key, i);
            } catch (const std::exception& e) {
                r.failures.push_back({"frame refused", e.what(), 1});
                r.note = std::string("not run: ") + e.what();
            }
            progress.step();
        }
    } catch (const std::exception& e) {
        // No device, or the reference could not be drawn: nothing to measure against.
        for (MethodResult& r : report.methods)
            if (!r.ran && r.note.empty()) r.note = std::string("not run: ") + e.what();
    }
    progress.finish();
    return report;
}

} // namespace

std::unique_ptr<Family> make_lighting_family(const LightingFamilyOptions& options) {
    return std::make_unique<LightingFamily>(options);
}

} // namespace sherpa::lab
