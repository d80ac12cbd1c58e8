// The mesh-compression family: KHR_mesh_quantization presets (as gltfpack writes them)
// and meshoptimizer's codecs over the same streams, on every primitive of the scene,
// against the uncompressed geometry.
#include <sherpa/lab/families.h>
#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/image.h>
#include <sherpa/texture/source_export.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "lab_support.h"
#include "mesh_codec.h"

namespace sherpa::lab {
namespace {

using detail::QuantizationPreset;

// Bits rise together along each group, so every error falls along it. {14, 8, 12} is
// gltfpack's default (-vp 14 -vn 8 -vt 12); with octahedral normals through meshopt's
// filter, what gltfpack -cc writes.
constexpr std::array<QuantizationPreset, 16> kMethods{{
    {0, 0, 0},
    {8, 8, 8},
    {10, 8, 10},
    {12, 8, 12},
    {14, 8, 12},
    {14, 12, 14},
    {16, 16, 16},
    {0, 0, 0, true},
    {8, 8, 8, true},
    {10, 8, 10, true},
    {12, 8, 12, true},
    {14, 8, 12, true},
    {14, 12, 14, true},
    {16, 16, 16, true},
    {14, 8, 12, true, true},
    {16, 16, 16, true, true},
}};

MethodInfo method_info(const QuantizationPreset& p) {
    MethodInfo m;
    const bool is_float = p.position == 0;
    m.name = std::string(is_float ? "float" : "quantized") + (p.meshopt ? "+meshopt" : "") +
             (p.octahedral ? "-oct" : "");
    m.parameters = is_float ? "32-bit float"
                            : "vp=" + std::to_string(p.position) +
                                  " vn=" + std::to_string(p.normal) + " vt=" + std::to_string(p.uv);
    m.description = is_float
                        ? "uncompressed float streams (the reference)"
                        : "KHR_mesh_quantization: positions as integers on the mesh's bounds, "
                          "normals/tangents signed normalized, uvs normalized over their range";
    if (p.octahedral) m.description += "; normals/tangents octahedral (meshopt OCTAHEDRAL filter)";
    if (p.meshopt) m.description += "; bytes: meshopt_encodeVertexBuffer/IndexBuffer";
    m.group = p.meshopt ? "meshopt codec" : "KHR_mesh_quantization";
    return m;
}

struct Input {
    const scene::Mesh* mesh = nullptr;
    glm::mat4 world{1.0f};
    detail::MeshStreams streams;
    // The base colour texture's size in texels (0: none or unreadable), the uv set it
    // samples and its KHR_texture_transform's linear part.
    glm::dvec2 texels{0.0};
    std::uint32_t uv_set = 0;
    glm::dmat2 uv_matrix{1.0};
};

// Error sums of one method over the whole scene.
struct Tally {
    double pos_max = 0, pos_sq = 0, step = 0;
    double nrm_sum = 0, nrm_max = 0, tan_sum = 0, tan_max = 0, uv_max = 0, uv_sq = 0;
    double texel_max = 0, texel_sq = 0;
    std::uint64_t texel_n = 0;
    std::uint64_t pos_n = 0, nrm_n = 0, tan_n = 0, uv_n = 0, vertices = 0;
    std::uint64_t vertex_bytes = 0, index_bytes = 0;
    double ms = 0;
    std::map<std::pair<std::string, std::string>, std::uint64_t> failures; // (cause, where)
};

bool finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Angle in degrees between two directions (object space), or -1 when one is not a
// usable direction.
double angle_deg(glm::vec3 a, glm::vec3 b) {
    const double la = glm::length(glm::dvec3(a)), lb = glm::length(glm::dvec3(b));
    if (!finite(a) || !finite(b) || !(la > 1e-12) || !(lb > 1e-12)) return -1.0;
    if (a == b) return 0.0; // acos near 1 would give 1e-6 degrees for the float reference
    const double c = glm::dot(glm::dvec3(a), glm::dvec3(b)) / (la * lb);
    return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

void add_uv(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b, Tally& t) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = glm::length(glm::dvec2(a[i]) - glm::dvec2(b[i]));
        if (!std::isfinite(d)) continue;
        t.uv_max = std::max(t.uv_max, d), t.uv_sq += d * d, ++t.uv_n;
    }
}

// The decoded streams of one primitive against its source.
void measure(const Input& in, const detail::EncodedMesh& e, Tally& t) {
    const detail::MeshStreams &s = in.streams, &d = e.decoded;
    const std::string where = detail::describe_mesh(*in.mesh);
    // In double: coordinates near the float range under a scale stay finite.
    const glm::dmat4 world(in.world);
    std::uint64_t lost = 0;
    for (std::size_t i = 0; i < s.position.size(); ++i) {
        if (!finite(s.position[i])) continue; // an input failure, counted once
        const glm::dvec3 a(world * glm::dvec4(glm::dvec3(s.position[i]), 1.0)),
            b(world * glm::dvec4(glm::dvec3(d.position[i]), 1.0));
        const double dist = glm::length(a - b);
        if (!std::isfinite(dist)) {
            ++lost; // a non-finite node transform
            continue;
        }
        t.pos_max = std::max(t.pos_max, dist), t.pos_sq += dist * dist, ++t.pos_n;
    }
    if (lost) t.failures[{"non-finite world position (node transform)", where}] += lost;
    t.step = std::max(t.step, e.position_step * double(glm::length(glm::vec3(in.world[0]))));
    for (std::size_t i = 0; i < s.normal.size(); ++i)
        if (const double a = angle_deg(s.normal[i], d.normal[i]); a >= 0.0)
            t.nrm_sum += a, t.nrm_max = std::max(t.nrm_max, a), ++t.nrm_n;
    std::uint64_t flips = 0;
    for (std::size_t i = 0; i < s.tangent.size(); ++i) {
        const double a = angle_deg(glm::vec3(s.tangent[i]), glm::vec3(d.tangent[i]));
        if (a < 0.0) continue;
        t.tan_sum += a, t.tan_max = std::max(t.tan_max, a), ++t.tan_n;
        if (s.normal.empty()) continue;
        // The bitangent the shader derives, cross(n, t) * w, must keep its side.
        const glm::vec3 b0 = glm::cross(s.normal[i], glm::vec3(s.tangent[i])) * s.tangent[i].w;
        const glm::vec3 b1 = glm::cross(d.normal[i], glm::vec3(d.tangent[i])) * d.tangent[i].w;
        if (glm::length(b0) > 1e-3f && !(glm::dot(b0, b1) > 0.0f)) ++flips;
    }
    add_uv(s.uv0, d.uv0, t);
    add_uv(s.uv1, d.uv1, t);
    const std::vector<glm::vec2>&src = in.uv_set ? s.uv1 : s.uv0, &dec = in.uv_set ? d.uv1 : d.uv0;
    if (in.texels.x > 0.0)
        for (std::size_t i = 0; i < src.size(); ++i) {
            const double px =
                glm::length(in.texels * (in.uv_matrix * (glm::dvec2(src[i]) - glm::dvec2(dec[i]))));
            if (!std::isfinite(px)) continue;
            t.texel_max = std::max(t.texel_max, px), t.texel_sq += px * px, ++t.texel_n;
        }
    if (flips) t.failures[{"tangent frame flipped (bitangent reversed)", where}] += flips;
    if (e.zero_normals)
        t.failures[{"normal or tangent quantized to zero", where}] += e.zero_normals;
    if (!e.codec_error.empty()) t.failures[{e.codec_error, where}] += 1;
    t.vertices += s.position.size();
    t.vertex_bytes += e.vertex_bytes, t.index_bytes += e.index_bytes;
}

detail::MeshStreams streams_of(const scene::Mesh& m) {
    detail::MeshStreams s;
    auto has = [&](scene::VertexAttribute a) {
        return m.provenance_of(a) != scene::Provenance::Defaulted;
    };
    for (const scene::Vertex& v : m.vertices) {
        s.position.push_back(v.position);
        if (has(scene::VertexAttribute::Normal)) s.normal.push_back(v.normal);
        if (has(scene::VertexAttribute::Tangent)) s.tangent.push_back(v.tangent);
        if (has(scene::VertexAttribute::TexCoord0)) s.uv0.push_back(v.uv0);
        if (has(scene::VertexAttribute::TexCoord1)) s.uv1.push_back(v.uv1);
    }
    s.indices = m.indices;
    s.triangles = m.topology() == scene::Topology::Triangles;
    return s;
}

// Sizes of the scene's images in texels, read from their headers once per image (0
// where the header cannot be read, as for KTX2 here: no texel figure there).
class ImageSizes {
public:
    explicit ImageSizes(const scene::Scene& scene) : scene_(scene) {}
    glm::dvec2 of(std::int32_t image) {
        if (image < 0 || std::size_t(image) >= scene_.images.size()) return glm::dvec2(0.0);
        const auto [it, fresh] = sizes_.try_emplace(image, 0.0);
        if (!fresh) return it->second;
        const scene::ImageRecord& img = scene_.images[std::size_t(image)];
        std::uint32_t w = img.width, h = img.height;
        std::string error;
        if ((w == 0 || h == 0) && !img.encoded.empty() &&
            !tex::probe_encoded_image(img.encoded, tex::image_decoder_hint(img), error, &w, &h))
            unreadable.push_back(scene::image_location(scene_, image));
        return it->second = glm::dvec2(w, h);
    }
    std::vector<std::string> unreadable;

private:
    const scene::Scene& scene_;
    std::map<std::int32_t, glm::dvec2> sizes_;
};

void set_texture(const scene::Scene& scene, ImageSizes& sizes, Input& in) {
    if (in.mesh->material_id >= scene.materials.size()) return;
    const scene::TextureSlot& base = scene.materials[in.mesh->material_id].base_color;
    if (!base.present() || std::size_t(base.texture) >= scene.textures.size() || base.tex_coord > 1)
        return;
    in.texels = sizes.of(scene.textures[std::size_t(base.texture)].image);
    in.uv_set = base.tex_coord;
    if (base.transform.present) in.uv_matrix = glm::dmat2(glm::mat2(base.transform.matrix()));
}

// The primitives to measure (under their first instance's transform); what cannot be
// measured at all goes to `failures` for every method.
std::vector<Input> inputs_of(const scene::Scene& scene, std::vector<Failure>& failures,
                             ImageSizes& sizes) {
    std::vector<Input> out;
    // Each mesh's first instance, in one pass over the instances (not one per mesh).
    std::vector<const scene::MeshInstance*> first(scene.meshes.size(), nullptr);
    for (const scene::MeshInstance& inst : scene.instances)
        if (inst.mesh_id < first.size() && !first[inst.mesh_id]) first[inst.mesh_id] = &inst;
    for (std::uint32_t id = 0; id < scene.meshes.size(); ++id) {
        const scene::Mesh& m = scene.meshes[id];
        if (m.vertices.empty()) continue;
        std::uint64_t bad = 0;
        for (const scene::Vertex& v : m.vertices) bad += !finite(v.position);
        if (bad == m.vertices.size()) {
            failures.push_back({"no finite POSITION", detail::describe_mesh(m), bad});
            continue;
        }
        if (bad)
            failures.push_back({"non-finite POSITION (left out)", detail::describe_mesh(m), bad});
        Input in;
        in.mesh = &m;
        if (first[id]) in.world = first[id]->world;
        in.streams = streams_of(m);
        set_texture(scene, sizes, in);
        out.push_back(std::move(in));
    }
    return out;
}

MethodResult result_of(const MethodInfo& info, const Tally& t, const std::vector<Failure>& input) {
    MethodResult r;
    r.method = info;
    r.ran = true;
    r.total_ms = t.ms;
    r.time = t.ms / (double(t.vertices) / 1e6);
    auto rms = [](double sq, std::uint64_t n) { return n ? std::sqrt(sq / double(n)) : 0.0; };
    r.errors = {{"position_rms", rms(t.pos_sq, t.pos_n)},
                {"position_max", t.pos_max},
                {"position_step", t.step},
                {"bytes", double(t.vertex_bytes + t.index_bytes)},
                {"vertex_bytes", double(t.vertex_bytes)},
                {"index_bytes", double(t.index_bytes)},
                {"bytes_per_vertex", double(t.vertex_bytes) / double(t.vertices)}};
    if (t.nrm_n) {
        r.errors.push_back({"normal_mean_deg", t.nrm_sum / double(t.nrm_n)});
        r.errors.push_back({"normal_max_deg", t.nrm_max});
    }
    if (t.tan_n) {
        r.errors.push_back({"tangent_mean_deg", t.tan_sum / double(t.tan_n)});
        r.errors.push_back({"tangent_max_deg", t.tan_max});
    }
    if (t.uv_n) {
        r.errors.push_back({"uv_rms", rms(t.uv_sq, t.uv_n)});
        r.errors.push_back({"uv_max", t.uv_max});
    }
    if (t.texel_n) {
        r.errors.push_back({"uv_rms_texels", rms(t.texel_sq, t.texel_n)});
        r.errors.push_back({"uv_max_texels", t.texel_max});
    }
    r.failures = input;
    for (const auto& [key, count] : t.failures)
        r.failures.push_back({key.first, key.second, count});
    r.note = std::to_string(t.vertices) + " vertices";
    return r;
}

class MeshCompressionFamily final : public Family {
public:
    explicit MeshCompressionFamily(const MeshCompressionFamilyOptions& options)
        : options_(options) {}
    std::string_view name() const override { return "mesh-compression"; }
    std::vector<MethodInfo> methods() const override {
        std::vector<MethodInfo> out;
        for (const QuantizationPreset& p : kMethods) out.push_back(method_info(p));
        return out;
    }
    FamilyReport run(const scene::Scene& scene, const RunControl& control) const override;

private:
    MeshCompressionFamilyOptions options_;
};

FamilyReport MeshCompressionFamily::run(const scene::Scene& scene,
                                        const RunControl& control) const {
    FamilyReport report;
    report.family = "mesh-compression";
    report.reference = "the file's float geometry (positions in world space)";
    report.time_unit = "ms/Mvert";
    report.chart_error = "position_rms";
    report.chart_x = "bytes";
    const std::vector<MethodInfo> infos = methods();
    std::vector<Failure> input_failures;
    ImageSizes sizes(scene);
    const std::vector<Input> inputs = inputs_of(scene, input_failures, sizes);
    detail::Progress progress(control, inputs.size() * infos.size());
    if (progress.stop()) return detail::cancelled_report(report.family);
    std::vector<Tally> tallies(infos.size());
    for (const Input& in : inputs)
        for (std::size_t k = 0; k < infos.size(); ++k) {
            if (progress.stop()) return detail::cancelled_report(report.family);
            detail::EncodedMesh e;
            double best = 1e300;
            for (int r = 0; r < std::max(1, options_.repeat); ++r) {
                const double t0 = detail::thread_cpu_ms();
                e = detail::encode_mesh(in.streams, kMethods[k]);
                best = std::min(best, detail::thread_cpu_ms() - t0);
            }
            tallies[k].ms += best;
            measure(in, e, tallies[k]);
            progress.step();
        }
    const bool any_vertices = std::any_of(scene.meshes.begin(), scene.meshes.end(),
                                          [](const scene::Mesh& m) { return !m.vertices.empty(); });
    const std::string why =
        any_vertices ? "no primitive with finite positions" : "no mesh primitive with vertices";
    for (std::size_t k = 0; k < infos.size(); ++k) {
        if (inputs.empty()) {
            MethodResult r;
            r.method = infos[k];
            r.note = why;
            r.failures = input_failures;
            report.methods.push_back(std::move(r));
            continue;
        }
        report.methods.push_back(result_of(infos[k], tallies[k], input_failures));
    }
    if (inputs.empty()) report.notes.push_back(why + ": nothing to quantize");
    report.notes.push_back(
        "errors: positions in world space under each primitive's first instance; "
        "normal/tangent angles in object space; uv in uv units (no texture "
        "transform), uv_*_texels in texels of the base colour texture (through its "
        "transform); time: CPU encode+decode, best of " +
        std::to_string(std::max(1, options_.repeat)));
    for (const std::string& image : sizes.unreadable)
        report.notes.push_back("no uv error in texels on " + image + ": its size is unreadable");
    return report;
}

} // namespace

std::unique_ptr<Family> make_mesh_compression_family(const MeshCompressionFamilyOptions& options) {
    return std::make_unique<MeshCompressionFamily>(options);
}

} // namespace sherpa::lab
