// The shadows family: cascaded shadow map settings against ray-traced hard shadows,
// per pixel through the renderer's shadow-error view (lab/families.h).
#include <sherpa/gpu/context.h>
#include <sherpa/lab/families.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/render/renderer.h>
#include <sherpa/render/shadow_error.h>
#include <sherpa/scene/framing.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <exception>

#include "lab_gpu.h"

namespace sherpa::lab {
namespace {

constexpr const char* kReference =
    "ray-traced hard shadows: one shadow ray per pixel from the primary hit toward the sun "
    "(render --renderer rt --view shadow)";

// `count` cameras around the scene, 20 degrees up, looking at its centre: even ones
// at the framing distance (the culling path's outside half, turned off the axes), odd
// ones at 40% of it, close up. Framed cameras see the whole scene in every depth slice
// of the cascade fit, so each cascade is the scene's own sphere (shadow_cascades.cpp:
// never wider than the scene) and more cascades change nothing; close ones split it.
std::vector<scene::CameraSpec> orbit(const core::Aabb& bounds, std::uint32_t count, float aspect) {
    const core::Aabb box =
        bounds.valid() ? bounds : core::Aabb::from_min_max(glm::vec3(-1), glm::vec3(1));
    scene::FramingOptions framing;
    framing.aspect = aspect;
    std::vector<scene::CameraSpec> out;
    const float elevation = glm::radians(20.0f);
    for (std::uint32_t i = 0; i < count; ++i) {
        const float az = 0.6f + 2.0f * glm::pi<float>() * float(i) / float(std::max(count, 1u));
        const glm::vec3 dir(std::cos(elevation) * std::sin(az), std::sin(elevation),
                            std::cos(elevation) * std::cos(az));
        scene::CameraSpec c = scene::frame_box_along(box, dir, framing);
        if (i % 2 == 1) {
            c.eye = c.target + 0.4f * (c.eye - c.target);
            c.near_plane *= 0.4f;
        }
        out.push_back(c);
    }
    return out;
}

struct Tally {
    render::ShadowErrorCounts n;
    double ms = 0.0, total_ms = 0.0;
    std::uint32_t timed = 0;
    std::vector<Failure> failures;

    void result(MethodResult& r) const {
        r.ran = true;
        r.time = timed ? ms / timed : 0.0;
        r.total_ms = total_ms;
        const double lit = double(std::max<std::uint64_t>(n.lit(), 1));
        r.errors = {{"lit_pixels_wrong_percent", n.percent_of_lit_wrong()},
                    {"false_shadow_percent", 100.0 * double(n.false_shadow) / lit},
                    {"false_light_percent", 100.0 * double(n.false_light) / lit},
                    {"wrong_pixels", double(n.wrong())},
                    {"lit_pixels", double(n.lit()), true}};
        r.failures = failures;
    }
};

class ShadowFamily final : public Family {
public:
    explicit ShadowFamily(ShadowFamilyOptions options) : options_(std::move(options)) {}
    std::string_view name() const override { return "shadows"; }

    std::vector<MethodInfo> methods() const override {
        std::vector<MethodInfo> out;
        for (std::uint32_t res : options_.resolutions)
            for (std::uint32_t c : options_.cascades)
                for (std::uint32_t t : options_.pcf_taps)
                    out.push_back({shadow_method_name(res, c, t),
                                   "resolution=" + std::to_string(res) + " cascades=" +
                                       std::to_string(c) + " taps=" + std::to_string(t),
                                   "cascaded shadow maps, " + std::to_string(res) + "x" +
                                       std::to_string(res) + " texels per cascade, " +
                                       std::to_string(t) + " PCF taps",
                                   ""});
        return out;
    }

    FamilyReport run(const scene::Scene& scene, const RunControl& control) const override {
        FamilyReport report;
        report.family = std::string(name());
        report.reference = kReference;
        report.time_unit = "ms/frame";
        report.chart_error = "lit_pixels_wrong_percent";
        for (const MethodInfo& m : methods()) {
            MethodResult r;
            r.method = m;
            report.methods.push_back(std::move(r));
        }
        const float aspect = float(options_.width) / float(std::max(options_.height, 1u));
        const std::vector<scene::CameraSpec> cameras =
            orbit(scene.bounds, options_.cameras, aspect);
        report.notes.push_back(
            std::to_string(cameras.size()) + " cameras (framed and close up, alternately) at " +
            std::to_string(options_.width) + "x" + std::to_string(options_.height) +
            ", time: median of " + std::to_string(options_.frames) +
            " lit frames (cascades redrawn each frame)");
        detail::Progress progress(control, report.methods.size() * cameras.size());
        if (progress.stop()) return detail::cancelled_report(report.family);
        try {
            gpu::Context context(detail::family_context(options_.validation, options_.ray_tracing));
            if (!detail::ray_traces(context, report, progress, "no reference to measure against"))
                return report;
            std::size_t index = 0;
            for (std::uint32_t res : options_.resolutions) {
                const std::size_t first = index;
                index += options_.cascades.size() * options_.pcf_taps.size();
                try {
                    if (!run_resolution(context, scene, cameras, res, first, report, progress))
                        return detail::cancelled_report(report.family);
                } catch (const std::exception& e) {
                    for (std::size_t i = first; i < index; ++i)
                        if (!report.methods[i].ran) report.methods[i].note = e.what();
                }
            }
        } catch (const std::exception& e) {
            for (MethodResult& r : report.methods)
                if (!r.ran) r.note = std::string("no Vulkan device: ") + e.what();
        }
        progress.finish();
        return report;
    }

private:
    // The methods of one map resolution (one renderer: the resolution is fixed at
    // its creation), from report.methods[first]. False when cancelled.
    bool run_resolution(gpu::Context& context, const scene::Scene& scene,
                        const std::vector<scene::CameraSpec>& cameras, std::uint32_t resolution,
                        std::size_t first, FamilyReport& report, detail::Progress& progress) const {
        render::RendererOptions ro;
        ro.ray_tracing = true;
        ro.shadow_resolution = resolution;
        render::Renderer renderer(context, ro);
        renderer.set_environment(options_.lighting.environment.get());
        renderer.load(scene);
        std::size_t i = first;
        for (std::uint32_t cascades : options_.cascades)
            for (std::uint32_t taps : options_.pcf_taps) {
                Tally tally;
                for (std::size_t c = 0; c < cameras.size(); ++c) {
                    if (progress.stop()) return false;
                    measure(context, renderer, cameras[c], c, cascades, taps, tally);
                    progress.step();
                }
                tally.result(report.methods[i]);
                report.methods[i].note = context.info().name;
                ++i;
            }
        return true;
    }

    void measure(gpu::Context& context, render::Renderer& renderer, const scene::CameraSpec& camera,
                 std::size_t index, std::uint32_t cascades, std::uint32_t taps,
                 Tally& tally) const {
        const std::size_t seen = context.validation().count();
        const double t0 = detail::process_cpu_ms();
        render::FrameRequest s;
        render::copy_lighting(options_.lighting.settings, s);
        s.width = options_.width;
        s.height = options_.height;
        s.camera = render::explicit_camera(camera);
        s.cascades = cascades;
        s.shadow_pcf_taps = taps;
        s.cache_shadows = false;     // every frame pays for its cascades
        renderer.render(s, nullptr); // pipelines made outside the timed frames
        std::vector<double> ms;
        for (std::uint32_t f = 0; f < std::max(options_.frames, 1u); ++f)
            ms.push_back(renderer.render(s, nullptr).gpu_ms);
        if (context.info().timestamps) {
            tally.ms += detail::median(ms);
            ++tally.timed;
        }
        s.renderer = render::RendererKind::RayTraced;
        s.view = render::DebugView::ShadowError;
        std::vector<std::uint8_t> rgba;
        renderer.render(s, &rgba);
        const render::ShadowErrorCounts n = render::count_shadow_error(rgba);
        const std::string where = "camera " + std::to_string(index);
        if (n.lit() == 0) tally.failures.push_back({"no lit pixels (rays)", where, 1});
        tally.n.agree_lit += n.agree_lit;
        tally.n.agree_shadowed += n.agree_shadowed;
        tally.n.false_shadow += n.false_shadow;
        tally.n.false_light += n.false_light;
        tally.n.other += n.other;
        const auto& messages = context.validation().messages();
        for (std::size_t m = seen; m < messages.size(); ++m)
            tally.failures.push_back({"validation message", where + ": " + messages[m].id_name, 1});
        tally.total_ms += detail::process_cpu_ms() - t0;
    }

    ShadowFamilyOptions options_;
};

} // namespace

std::string shadow_method_name(std::uint32_t resolution, std::uint32_t cascades,
                               std::uint32_t taps) {
    return std::to_string(resolution) + "x" + std::to_string(cascades) + " pcf" +
           std::to_string(taps);
}

bool parse_shadow_method(std::string_view name, std::uint32_t& resolution, std::uint32_t& cascades,
                         std::uint32_t& taps) {
    auto number = [&](std::string_view& s, std::uint32_t& out) {
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        if (ec != std::errc{}) return false;
        s.remove_prefix(std::size_t(end - s.data()));
        return true;
    };
    std::string_view s = name;
    if (!number(s, resolution) || s.substr(0, 1) != "x") return false;
    s.remove_prefix(1);
    if (!number(s, cascades) || s.substr(0, 4) != " pcf") return false;
    s.remove_prefix(4);
    return number(s, taps) && s.empty();
}

std::unique_ptr<Family> make_shadow_family(const ShadowFamilyOptions& options) {
    return std::make_unique<ShadowFamily>(options);
}

} // namespace sherpa::lab
