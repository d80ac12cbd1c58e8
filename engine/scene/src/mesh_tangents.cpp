// Tangents on engine meshes: per-corner results written into vertices with splitting,
// and the glTF rule deciding which meshes get generated tangents.
#include <atomic>
#include <cstring>
#include <stdexcept>

#include <sherpa/scene/material_extension_slots.h>
#include <sherpa/scene/mesh_tangents.h>

#include "tangent_internal.h"

namespace sherpa::scene {
namespace {

constexpr std::uint32_t kNone = ~0u;

bool same_bits(const glm::vec4& a, const glm::vec4& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

std::size_t attribute_slot(VertexAttribute a) {
    return static_cast<std::size_t>(a);
}

// The material whose normal texture decides the mesh's tangents: its own, else the
// first KHR_materials_variants material with one (a switch must find tangents).
const MaterialInstance* normal_mapped_material(const Scene& scene, std::uint32_t mesh) {
    const MaterialInstance* first = nullptr;
    for (std::uint32_t m : possible_materials(scene, mesh)) {
        if (m >= scene.materials.size()) continue;
        if (!first) first = &scene.materials[m];
        if (needs_tangents(scene.materials[m])) return &scene.materials[m];
    }
    return first;
}

} // namespace

std::uint32_t apply_corner_tangents(Mesh& mesh, std::span<const glm::vec4> corner_tangents) {
    if (corner_tangents.size() != mesh.indices.size())
        throw std::invalid_argument("apply_corner_tangents: one tangent per index expected");
    const std::size_t original_count = mesh.vertices.size();
    // Pass 1 decides which vertex carries each corner's tangent, without growing the mesh:
    // a vertex and its copies form a chain (next_copy), tangent_of holds each one's
    // tangent of this pass, source_of each copy's original; written[v] says whether v
    // has a tangent of this pass yet.
    std::vector<glm::vec4> tangent_of(original_count);
    std::vector<std::uint32_t> next_copy(original_count, kNone), source_of;
    std::vector<std::uint8_t> written(original_count, 0);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const glm::vec4& tangent = corner_tangents[c];
        const std::uint32_t original = mesh.indices[c];
        if (!written[original]) {
            tangent_of[original] = tangent;
            written[original] = 1;
            continue;
        }
        // Walk the copies for one holding this exact tangent; add a copy otherwise.
        std::uint32_t v = original, last = original;
        while (v != kNone && !same_bits(tangent_of[v], tangent)) {
            last = v;
            v = next_copy[v];
        }
        if (v == kNone) {
            v = static_cast<std::uint32_t>(tangent_of.size());
            tangent_of.push_back(tangent);
            next_copy.push_back(kNone);
            next_copy[last] = v;
            source_of.push_back(original);
        }
        mesh.indices[c] = v;
    }
    // Pass 2 grows the mesh once and writes the tangents.
    const bool has_colors = mesh.colors.size() == original_count;
    mesh.vertices.reserve(tangent_of.size());
    for (std::uint32_t source : source_of) mesh.vertices.push_back(mesh.vertices[source]);
    if (!source_of.empty()) { // copies name their original's source vertex
        if (mesh.source_vertex.empty()) {
            mesh.source_vertex.resize(original_count);
            for (std::uint32_t v = 0; v < original_count; ++v) mesh.source_vertex[v] = v;
        }
        for (std::uint32_t source : source_of)
            mesh.source_vertex.push_back(mesh.source_vertex[source]);
    }
    if (has_colors) {
        mesh.colors.reserve(tangent_of.size());
        for (std::uint32_t source : source_of) mesh.colors.push_back(mesh.colors[source]);
    }
    for (std::size_t v = 0; v < tangent_of.size(); ++v)
        if (v >= original_count || written[v]) mesh.vertices[v].tangent = tangent_of[v];
    return static_cast<std::uint32_t>(source_of.size());
}

std::uint32_t normal_uv_set(const Scene& scene, const Mesh& mesh) {
    if (mesh.material_id >= scene.materials.size()) return 0;
    return tangent_uv_set(scene.materials[mesh.material_id]);
}

MeshTangentInput tangent_input_of(const Mesh& mesh, std::uint32_t tex_coord) {
    MeshTangentInput input;
    input.positions.reserve(mesh.vertices.size());
    input.normals.reserve(mesh.vertices.size());
    input.uvs.reserve(mesh.vertices.size());
    for (const Vertex& v : mesh.vertices) {
        input.positions.push_back(v.position);
        input.normals.push_back(v.normal);
        input.uvs.push_back(tex_coord == 1 ? v.uv1 : v.uv0);
    }
    return input;
}

TangentInput MeshTangentInput::view(const Mesh& mesh) const {
    return TangentInput{positions, normals, uvs, mesh.indices};
}

MeshTangentReport generate_mesh_tangents(Mesh& mesh, std::uint32_t tex_coord, TangentMethod method,
                                         TangentWorkspace* workspace) {
    MeshTangentReport report;
    report.tex_coord = tex_coord > 1 ? 0 : tex_coord;
    if (tex_coord > 1)
        report.reason = "TEXCOORD_" + std::to_string(tex_coord) + " is not kept; used TEXCOORD_0";
    // The mesh's streams and the per-corner result live in the workspace, so a thread
    // working through a scene's meshes reuses their memory.
    TangentWorkspace local;
    tangent_detail::MeshScratch& scratch = (workspace ? *workspace : local).buffers().mesh;
    const std::size_t vertex_count = mesh.vertices.size();
    scratch.positions.resize(vertex_count);
    scratch.normals.resize(vertex_count);
    scratch.uvs.resize(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) {
        const Vertex& v = mesh.vertices[i];
        scratch.positions[i] = v.position;
        scratch.normals[i] = v.normal;
        scratch.uvs[i] = report.tex_coord == 1 ? v.uv1 : v.uv0;
    }
    scratch.corners.resize(mesh.indices.size());
    const TangentInput input{scratch.positions, scratch.normals, scratch.uvs, mesh.indices};
    report.stats = generate_corner_tangents(input, method, scratch.corners, {},
                                            workspace ? workspace : &local);
    report.split_vertices = apply_corner_tangents(mesh, scratch.corners);
    mesh.provenance[attribute_slot(VertexAttribute::Tangent)] = Provenance::Generated;
    report.generated = true;
    return report;
}

SceneTangentReport generate_scene_tangents(Scene& scene, const SceneTangentOptions& options) {
    SceneTangentReport report;
    report.meshes.resize(scene.meshes.size());
    const auto mesh_count = static_cast<std::int64_t>(scene.meshes.size());
    std::atomic<std::size_t> meshes_done{0};
    // Threads only where there is work to share: starting the OpenMP team costs a
    // scene without normal textures (most files) ~30-90 ms of wall time on a loaded
    // machine (its threads wait to be scheduled), for nothing to do.
    std::size_t corners_to_generate = 0, meshes_to_generate = 0;
    for (std::uint32_t id = 0; id < scene.meshes.size(); ++id) {
        const Mesh& mesh = scene.meshes[id];
        const MaterialInstance* material = normal_mapped_material(scene, id);
        const bool normal_texture = material && needs_tangents(*material);
        const bool authored = mesh.provenance_of(VertexAttribute::Tangent) == Provenance::Authored;
        if (mesh.topology() == Topology::Triangles &&
            (options.regenerate || (!authored && normal_texture))) {
            corners_to_generate += mesh.indices.size();
            ++meshes_to_generate;
        }
    }
    constexpr std::size_t kParallelCorners = 30000; // below: the team costs more than it saves
    const bool parallel = meshes_to_generate > 1 && corners_to_generate >= kParallelCorners;
    // Meshes are independent; dynamic scheduling because their sizes vary by orders of
    // magnitude. Exceptions cannot cross the OpenMP region, so they become reasons.
#pragma omp parallel if (parallel)
    {
        TangentWorkspace workspace;
#pragma omp for schedule(dynamic, 1)
        for (std::int64_t i = 0; i < mesh_count; ++i) {
            if (core::is_cancelled(options.cancel)) continue;
            Mesh& mesh = scene.meshes[static_cast<std::size_t>(i)];
            MeshTangentReport& out = report.meshes[static_cast<std::size_t>(i)];
            // Reports the mesh as done however the body below leaves it.
            struct Done {
                const SceneTangentOptions& o;
                std::atomic<std::size_t>& n;
                std::size_t total;
                ~Done() {
                    const std::size_t d = ++n;
                    if (o.progress) o.progress(d, total);
                }
            } done{options, meshes_done, static_cast<std::size_t>(mesh_count)};
            const bool authored =
                mesh.provenance_of(VertexAttribute::Tangent) == Provenance::Authored;
            const MaterialInstance* material =
                normal_mapped_material(scene, static_cast<std::uint32_t>(i));
            const bool normal_texture = material && needs_tangents(*material);
            if (mesh.topology() != Topology::Triangles) {
                out.reason = "lines and points have no surface: no tangents";
                continue;
            }
            if (!options.regenerate && authored) {
                out.reason = "authored TANGENT kept";
                continue;
            }
            if (!options.regenerate && !normal_texture) {
                out.reason = "no normal texture or anisotropy: tangents not needed";
                continue;
            }
            const std::uint32_t set = normal_texture ? tangent_uv_set(*material) : 0;
            try {
                out = generate_mesh_tangents(mesh, set, options.method, &workspace);
                if (out.reason.empty()) out.reason = authored ? "regenerated" : "generated";
            } catch (const std::exception& e) {
                out.reason = std::string("tangent generation failed: ") + e.what();
            }
        }
    }
    for (const MeshTangentReport& m : report.meshes) {
        if (!m.generated) continue;
        ++report.generated_meshes;
        report.split_vertices += m.split_vertices;
        report.stats += m.stats;
    }
    return report;
}

void add_tangent_warnings(Scene& scene, const SceneTangentReport& report) {
    for (std::size_t i = 0; i < report.meshes.size(); ++i) {
        const MeshTangentReport& m = report.meshes[i];
        const Mesh& mesh = scene.meshes[i];
        const std::string where = "mesh " + std::to_string(mesh.group_id) + " primitive " +
                                  std::to_string(mesh.primitive_index) + ": ";
        if (!m.generated) {
            if (m.reason.rfind("tangent generation failed", 0) == 0)
                scene.warnings.push_back(where + m.reason);
            continue;
        }
        if (m.reason != "generated") scene.warnings.push_back(where + m.reason);
        if (m.stats.fallbacks() == 0) continue;
        std::string causes;
        for (std::size_t c = 1; c < kTangentFallbackCauses; ++c)
            if (m.stats.corners[c] > 0)
                causes += (causes.empty() ? "" : ", ") + std::to_string(m.stats.corners[c]) + " " +
                          std::string(to_string(static_cast<TangentFallback>(c)));
        scene.warnings.push_back(where + std::to_string(m.stats.fallbacks()) +
                                 " corners got fallback tangents (" + causes + ")");
    }
}

} // namespace sherpa::scene
