// The culling family: the CPU tests of culling.h and the GPU shader of cull_check.h
// over a camera path, against the exact test.
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/lab/families.h>
#include <sherpa/render/cull_check.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/framing.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "lab_support.h"

namespace sherpa::lab {
namespace {

constexpr scene::CullMethod kCpuMethods[] = {scene::CullMethod::Sphere, scene::CullMethod::PVertex,
                                             scene::CullMethod::Exact};

// Counts of one method over the path, against the exact test's visible flags.
struct Tally {
    std::uint64_t tested = 0, false_positives = 0, false_negatives = 0;
    double ms = 0.0;
    std::vector<Failure> failures;

    void add(std::size_t camera, std::span<const std::uint8_t> visible,
             std::span<const std::uint8_t> exact) {
        std::uint64_t missed = 0;
        std::string which;
        for (std::size_t i = 0; i < exact.size(); ++i) {
            false_positives += visible[i] && !exact[i] ? 1 : 0;
            if (exact[i] && !visible[i]) {
                if (++missed <= 8) which += (missed > 1 ? ", " : " ") + std::to_string(i);
            }
        }
        tested += exact.size();
        false_negatives += missed;
        if (missed)
            failures.push_back({"false negative (visible, culled)",
                                "camera " + std::to_string(camera) + " instances" + which +
                                    (missed > 8 ? ", ..." : ""),
                                missed});
    }
    MethodResult result(MethodInfo info) const {
        MethodResult r;
        r.method = std::move(info);
        r.ran = true;
        r.total_ms = ms;
        r.time = tested ? ms * 1e6 / double(tested) : 0.0;
        r.errors.push_back({"false_positives", double(false_positives)});
        r.errors.push_back(
            {"false_positive_rate", tested ? double(false_positives) / double(tested) : 0.0});
        r.errors.push_back({"false_negatives", double(false_negatives)});
        r.failures = failures;
        return r;
    }
};

class CullFamily final : public Family {
public:
    explicit CullFamily(const CullFamilyOptions& options) : options_(options) {}
    std::string_view name() const override { return "culling"; }
    std::vector<MethodInfo> methods() const override {
        return {{"sphere", "", "bounding sphere of each box (CPU)", ""},
                {"pvertex", "", "AABB p-vertex against each plane (CPU)", ""},
                {"exact", "", "separating axes, box against frustum (CPU; the reference)", ""},
                {"gpu", "test=pvertex", "shaders/cull.comp, p-vertex (Vulkan device)", ""}};
    }
    FamilyReport run(const scene::Scene& scene, const RunControl& control) const override;

private:
    MethodResult run_gpu(const scene::Scene& scene, const std::vector<scene::Frustum>& frusta,
                         const std::vector<std::vector<std::uint8_t>>& exact,
                         detail::Progress& progress) const;
    CullFamilyOptions options_;
};

FamilyReport CullFamily::run(const scene::Scene& scene, const RunControl& control) const {
    FamilyReport report;
    report.family = "culling";
    report.reference = "the exact test (separating axes)";
    report.time_unit = "ns/object";
    report.chart_error = "false_positives";
    const std::vector<scene::CameraSpec> path =
        options_.path.empty() ? camera_path(scene.bounds, options_.path_length) : options_.path;
    std::vector<scene::Frustum> frusta;
    for (const scene::CameraSpec& c : path)
        frusta.push_back(scene::frustum_from_view_projection(c.view_projection()));
    report.notes.push_back(std::to_string(path.size()) + " cameras, " +
                           std::to_string(scene.instances.size()) + " objects");
    detail::Progress progress(control, frusta.size() * (std::size(kCpuMethods) + 1));
    const scene::BoxesSoA boxes = scene::instance_boxes(scene);
    const core::SimdLevel simd = core::best_simd_level();
    std::vector<std::vector<std::uint8_t>> exact(frusta.size());
    for (std::size_t c = 0; c < frusta.size(); ++c) {
        exact[c].resize(boxes.size());
        scene::cull_boxes(frusta[c], boxes, scene::CullMethod::Exact, simd, exact[c]);
    }
    std::vector<std::uint8_t> visible(boxes.size());
    for (scene::CullMethod method : kCpuMethods) {
        Tally tally;
        for (std::size_t c = 0; c < frusta.size(); ++c) {
            if (progress.stop()) return detail::cancelled_report(report.family);
            double best = 1e300;
            for (int r = 0; r < std::max(1, options_.repeat); ++r) {
                const double t0 = detail::thread_cpu_ms();
                scene::cull_boxes(frusta[c], boxes, method, simd, visible);
                best = std::min(best, detail::thread_cpu_ms() - t0);
            }
            tally.ms += best;
            tally.add(c, visible, exact[c]);
            progress.step();
        }
        MethodResult r = tally.result(methods()[std::size_t(method)]);
        r.note = std::string("SIMD ") + std::string(to_string(simd));
        report.methods.push_back(std::move(r));
    }
    report.methods.push_back(run_gpu(scene, frusta, exact, progress));
    if (progress.stop()) return detail::cancelled_report(report.family);
    progress.finish();
    return report;
}

MethodResult CullFamily::run_gpu(const scene::Scene& scene,
                                 const std::vector<scene::Frustum>& frusta,
                                 const std::vector<std::vector<std::uint8_t>>& exact,
                                 detail::Progress& progress) const {
    MethodResult out;
    out.method = methods()[3];
    if (!options_.gpu) {
        out.note = "GPU method not asked for";
        return out;
    }
    if (scene.instances.empty()) {
        out.note = "no objects to cull";
        return out;
    }
    try {
        gpu::ContextOptions co;
        co.validation = options_.gpu_validation;
        gpu::Context context(co);
        gpu::ResourceManager resources(context);
        render::GpuCullChecker check(context, resources, scene);
        // The first dispatch compiles the pipeline on lavapipe: keep it out of the timing.
        check.compare(frusta.front(), scene::CullMethod::PVertex, {});
        Tally tally;
        bool timed = true;
        std::vector<std::uint8_t> visible(scene.instances.size());
        for (std::size_t c = 0; c < frusta.size(); ++c) {
            if (progress.stop()) return out;
            const render::GpuCullComparison r =
                check.compare(frusta[c], scene::CullMethod::PVertex, exact[c]);
            std::fill(visible.begin(), visible.end(), 0);
            for (std::uint32_t i : r.visible) visible[i] = 1;
            timed &= r.gpu_ms >= 0.0;
            tally.ms += std::max(0.0, r.gpu_ms);
            tally.add(c, visible, exact[c]);
            progress.step();
        }
        for (const gpu::ValidationMessage& m : context.validation().messages())
            tally.failures.push_back({"validation message", m.id_name + ": " + m.text, 1});
        out = tally.result(out.method);
        out.note = context.info().name + (timed ? "" : " (no timestamps: time 0)");
    } catch (const std::exception& e) {
        out.note = std::string("no Vulkan device: ") + e.what();
    }
    return out;
}

} // namespace

std::vector<scene::CameraSpec> camera_path(const core::Aabb& bounds, std::uint32_t count) {
    const core::Aabb box =
        bounds.valid() ? bounds : core::Aabb::from_min_max(glm::vec3(-1), glm::vec3(1));
    const glm::vec3 centre = box.center();
    const float radius = std::max(0.5f * glm::length(box.extent()), 1e-6f);
    std::vector<scene::CameraSpec> path;
    const std::uint32_t outside = (count + 1) / 2, inside = count - outside;
    const float elevation = glm::radians(scene::kFramingElevationDegrees);
    for (std::uint32_t i = 0; i < outside; ++i) {
        const float az = 2.0f * glm::pi<float>() * float(i) / float(outside);
        const glm::vec3 dir(std::cos(elevation) * std::sin(az), std::sin(elevation),
                            std::cos(elevation) * std::cos(az));
        path.push_back(scene::frame_box_along(box, dir, scene::FramingOptions{}));
    }
    for (std::uint32_t i = 0; i < inside; ++i) {
        const float az = 2.0f * glm::pi<float>() * (float(i) + 0.5f) / float(inside);
        const glm::vec3 out(std::sin(az), 0.0f, std::cos(az));
        scene::CameraSpec c;
        c.eye = centre + 0.5f * radius * out;
        c.target = c.eye + radius * out;
        c.near_plane = radius * 1e-3f;
        path.push_back(c);
    }
    return path;
}

std::unique_ptr<Family> make_cull_family(const CullFamilyOptions& options) {
    return std::make_unique<CullFamily>(options);
}

} // namespace sherpa::lab
