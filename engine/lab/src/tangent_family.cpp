// The tangents family: every method of tangents.h on every triangle mesh of the scene,
// against exact MikkTSpace and the file's authored tangents.
#include <sherpa/lab/families.h>
#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/tangent_compare.h>
#include <sherpa/scene/tangents.h>

#include <algorithm>

#include "lab_support.h"

namespace sherpa::lab {
namespace {

// Everything one method produced over the scene, corners of all meshes in a row.
struct Pooled {
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec4> on_authored; // the corners of meshes with authored tangents
    double cpu_ms = 0.0;
    scene::TangentStats stats;
    std::vector<Failure> failures;
};

void add_comparison(std::vector<ErrorFigure>& out, const std::string& prefix,
                    const scene::TangentComparison& c) {
    out.push_back({prefix + "mean_deg", c.mean});
    out.push_back({prefix + "p99_deg", c.p99});
    out.push_back({prefix + "max_deg", c.max});
    out.push_back({prefix + "flips", double(c.flips)});
}

std::uint64_t differing(std::span<const glm::vec4> a, std::span<const glm::vec4> b,
                        std::span<const std::uint8_t> skip) {
    std::uint64_t n = 0;
    for (std::size_t c = 0; c < a.size(); ++c)
        if (!skip[c] && (!(scene::tangent_angle_degrees(a[c], b[c]) <= kDifferingDegrees) ||
                         (a[c].w < 0.0f) != (b[c].w < 0.0f)))
            ++n;
    return n;
}

class TangentFamily final : public Family {
public:
    explicit TangentFamily(const TangentFamilyOptions& options) : options_(options) {}
    std::string_view name() const override { return "tangents"; }
    std::vector<MethodInfo> methods() const override {
        return {{"mikktspace", "", "exact MikkTSpace, one tangent per corner (the reference)", ""},
                {"mikktspace-welded", "", "MikkTSpace, last corner written per vertex", ""},
                {"lengyel", "", "per-triangle dP/du summed per vertex, Gram-Schmidt", ""}};
    }
    FamilyReport run(const scene::Scene& scene, const RunControl& control) const override;

private:
    TangentFamilyOptions options_;
};

FamilyReport TangentFamily::run(const scene::Scene& scene, const RunControl& control) const {
    FamilyReport report;
    report.family = "tangents";
    report.reference = "exact MikkTSpace (and the file's authored tangents where present)";
    report.time_unit = "ms/Mtri";
    report.chart_error = "angle_mean_deg";
    std::vector<const scene::Mesh*> meshes;
    std::uint64_t triangles = 0;
    for (const scene::Mesh& m : scene.meshes)
        if (m.topology() == scene::Topology::Triangles && !m.indices.empty()) meshes.push_back(&m);
    const std::size_t method_count = scene::kAllTangentMethods.size();
    detail::Progress progress(control, meshes.size() * method_count);
    if (progress.stop()) return detail::cancelled_report(report.family);
    std::vector<Pooled> pooled(method_count);
    std::vector<std::uint8_t> skip; // corners where exact MikkTSpace fell back
    std::vector<glm::vec4> authored;
    std::vector<Failure> input_failures;
    scene::TangentWorkspace workspace;
    for (const scene::Mesh* mesh : meshes) {
        // Vertex keeps uv sets 0 and 1: past them the loader makes tangents from uv 0.
        std::uint32_t set = scene::normal_uv_set(scene, *mesh);
        if (set > 1) set = 0;
        const scene::VertexAttribute uv_attr =
            set ? scene::VertexAttribute::TexCoord1 : scene::VertexAttribute::TexCoord0;
        if (mesh->provenance_of(uv_attr) == scene::Provenance::Defaulted) {
            input_failures.push_back({"no TEXCOORD_" + std::to_string(set),
                                      detail::describe_mesh(*mesh), mesh->indices.size()});
            for (std::size_t k = 0; k < method_count; ++k) progress.step();
            continue;
        }
        triangles += mesh->indices.size() / 3;
        const bool has_authored =
            mesh->provenance_of(scene::VertexAttribute::Tangent) == scene::Provenance::Authored;
        if (has_authored)
            for (std::uint32_t i : mesh->indices) authored.push_back(mesh->vertices[i].tangent);
        const scene::MeshTangentInput input = scene::tangent_input_of(*mesh, set);
        std::vector<glm::vec4> out(mesh->indices.size());
        std::vector<scene::TangentFallback> fallbacks(out.size());
        for (std::size_t k = 0; k < method_count; ++k) {
            if (progress.stop()) return detail::cancelled_report(report.family);
            Pooled& p = pooled[k];
            double best = 1e300;
            scene::TangentStats stats;
            for (int r = 0; r < std::max(1, options_.repeat); ++r) {
                const double t0 = detail::thread_cpu_ms();
                stats = scene::generate_corner_tangents(
                    input.view(*mesh), scene::kAllTangentMethods[k], out, fallbacks, &workspace);
                best = std::min(best, detail::thread_cpu_ms() - t0);
            }
            p.cpu_ms += best;
            p.stats += stats;
            for (std::size_t c = 1; c < scene::kTangentFallbackCauses; ++c)
                if (stats.corners[c])
                    p.failures.push_back({std::string(to_string(scene::TangentFallback(c))),
                                          detail::describe_mesh(*mesh), stats.corners[c]});
            p.tangents.insert(p.tangents.end(), out.begin(), out.end());
            if (has_authored) p.on_authored.insert(p.on_authored.end(), out.begin(), out.end());
            if (k == 0)
                for (scene::TangentFallback f : fallbacks)
                    skip.push_back(f != scene::TangentFallback::None);
            progress.step();
        }
    }
    if (triangles == 0) report.notes.push_back("no triangle mesh with texture coordinates");
    for (std::size_t k = 0; k < method_count; ++k) {
        const Pooled& p = pooled[k];
        MethodResult m;
        m.method = methods()[k];
        m.ran = true;
        m.total_ms = p.cpu_ms;
        m.time = triangles ? p.cpu_ms / (double(triangles) / 1e6) : 0.0;
        add_comparison(m.errors, "angle_",
                       scene::compare_tangents(p.tangents, pooled[0].tangents, skip));
        m.errors.push_back(
            {"differing_corners", double(differing(p.tangents, pooled[0].tangents, skip))});
        if (!authored.empty())
            add_comparison(m.errors, "authored_", scene::compare_tangents(p.on_authored, authored));
        m.errors.push_back({"fallback_corners", double(p.stats.fallbacks())});
        m.failures = input_failures;
        m.failures.insert(m.failures.end(), p.failures.begin(), p.failures.end());
        m.note = std::to_string(triangles) + " triangles";
        report.methods.push_back(std::move(m));
    }
    return report;
}

} // namespace

std::unique_ptr<Family> make_tangent_family(const TangentFamilyOptions& options) {
    return std::make_unique<TangentFamily>(options);
}

} // namespace sherpa::lab
