// glTF primitives -> engine meshes: attribute decoding, topology conversion,
// flat normals for primitives without NORMAL, validation.
#include "accessor_reader.h"
#include "import_context.h"
#include "import_error.h"
#include "motion_internal.h"

#include <cmath>
#include <cstdio>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

std::vector<std::uint32_t> to_triangle_list(PrimitiveMode mode,
                                            const std::vector<std::uint32_t>& in) {
    std::vector<std::uint32_t> out;
    const std::size_t n = in.size();
    switch (mode) {
    case PrimitiveMode::Triangles:
        out.assign(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
        break;
    case PrimitiveMode::TriangleStrip:
        // glTF: triangle i = {v_i, v_(i+1+i%2), v_(i+2-i%2)} keeps a consistent winding.
        for (std::size_t i = 0; i + 2 < n; ++i) {
            const std::size_t odd = i % 2;
            out.insert(out.end(), {in[i], in[i + 1 + odd], in[i + 2 - odd]});
        }
        break;
    case PrimitiveMode::TriangleFan:
        // glTF: triangle i = {v_(i+1), v_(i+2), v_0}.
        for (std::size_t i = 0; i + 2 < n; ++i)
            out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
        break;
    default:
        break;
    }
    return out;
}

// LINES, LINE_STRIP and LINE_LOOP as a line list (pairs of indices); POINTS as
// they are. glTF: LINES ignores a trailing odd index; a loop closes back to the
// first index.
std::vector<std::uint32_t> to_line_or_point_list(PrimitiveMode mode,
                                                 const std::vector<std::uint32_t>& in) {
    std::vector<std::uint32_t> out;
    const std::size_t n = in.size();
    switch (mode) {
    case PrimitiveMode::Points:
        out = in;
        break;
    case PrimitiveMode::Lines:
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 2));
        break;
    case PrimitiveMode::LineStrip:
    case PrimitiveMode::LineLoop:
        for (std::size_t i = 0; i + 1 < n; ++i) out.insert(out.end(), {in[i], in[i + 1]});
        if (mode == PrimitiveMode::LineLoop && n > 2) out.insert(out.end(), {in[n - 1], in[0]});
        break;
    default:
        break;
    }
    return out;
}

template <typename Apply>
void read_vec_attribute(ImportContext& ctx, const tinygltf::Primitive& prim, const char* name,
                        std::initializer_list<std::uint32_t> comps, std::uint32_t expected_count,
                        const std::string& where, Mesh& mesh, VertexAttribute attr, Apply&& apply) {
    const auto it = prim.attributes.find(name);
    const auto slot = static_cast<std::size_t>(attr);
    if (it == prim.attributes.end()) {
        mesh.provenance[slot] = Provenance::Defaulted;
        return;
    }
    const std::string path = where + ".attributes." + name;
    std::uint32_t nc = 0;
    const auto& model = ctx.model;
    const auto values = read_accessor_floats(model, it->second, comps, nc, path);
    ctx.check_declared_range(it->second, values, nc, path);
    if (values.size() / nc != expected_count)
        fail(path + ": has " + std::to_string(values.size() / nc) + " elements but POSITION has " +
             std::to_string(expected_count));
    for (std::uint32_t i = 0; i < expected_count; ++i) apply(i, &values[i * nc], nc);
    mesh.provenance[slot] = Provenance::Authored;
    mesh.sources[slot] = describe_accessor(model, it->second);
}

// Replaces the mesh's vertices by one vertex per triangle corner with the face
// normal, as glTF requires when NORMAL is absent.
std::uint32_t unweld_with_flat_normals(Mesh& mesh) {
    std::vector<Vertex> out;
    std::vector<glm::vec4> colors;
    std::vector<std::uint32_t> source;
    out.reserve(mesh.indices.size());
    source.reserve(mesh.indices.size());
    if (!mesh.colors.empty()) colors.reserve(mesh.indices.size());
    std::uint32_t degenerate = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[t]];
        const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        // Cross product in double: tiny or huge coordinates must not underflow to zero.
        const glm::dvec3 e1 = glm::dvec3(b.position) - glm::dvec3(a.position);
        const glm::dvec3 e2 = glm::dvec3(c.position) - glm::dvec3(a.position);
        glm::dvec3 n = glm::cross(e1, e2);
        const double len = glm::length(n);
        glm::vec3 normal(0.0f, 0.0f, 1.0f);
        if (len > 0.0 && std::isfinite(len))
            normal = glm::vec3(n / len);
        else
            ++degenerate;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = mesh.indices[t + static_cast<std::size_t>(k)];
            Vertex v = mesh.vertices[from];
            v.normal = normal;
            out.push_back(v);
            source.push_back(mesh.source_vertex.empty() ? from : mesh.source_vertex[from]);
            if (!mesh.colors.empty())
                colors.push_back(mesh.colors[mesh.indices[t + static_cast<std::size_t>(k)]]);
        }
    }
    mesh.vertices = std::move(out);
    mesh.colors = std::move(colors);
    mesh.source_vertex = std::move(source);
    for (std::uint32_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = i;
    mesh.unwelded = true;
    return degenerate;
}

// Gives each vertex whose normal is zero-length or not finite the area-weighted
// normal of the triangles around it (+Z where those are degenerate too).
void repair_invalid_normals(Mesh& mesh) {
    auto invalid = [](const glm::vec3& n) {
        const float len = glm::length(n);
        return !std::isfinite(len) || len == 0.0f;
    };
    std::vector<std::uint8_t> bad(mesh.vertices.size(), 0);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        bad[i] = invalid(mesh.vertices[i].normal);
    std::vector<glm::dvec3> sum(mesh.vertices.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (!bad[a] && !bad[b] && !bad[c]) continue;
        const glm::dvec3 pa(mesh.vertices[a].position);
        const glm::dvec3 n =
            glm::cross(glm::dvec3(mesh.vertices[b].position) - pa,
                       glm::dvec3(mesh.vertices[c].position) - pa); // length = 2 x area
        for (std::uint32_t v : {a, b, c})
            if (bad[v]) sum[v] += n;
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (!bad[i]) continue;
        const double len = glm::length(sum[i]);
        mesh.vertices[i].normal =
            len > 0.0 && std::isfinite(len) ? glm::vec3(sum[i] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

void import_primitive(ImportContext& ctx, std::uint32_t mesh_index, std::uint32_t prim_index) {
    const auto& model = ctx.model;
    const auto& prim = model.meshes[mesh_index].primitives[prim_index];
    const std::string where =
        "meshes[" + std::to_string(mesh_index) + "].primitives[" + std::to_string(prim_index) + "]";
    Scene& scene = ctx.scene;

    PrimitiveInfo info;
    info.mesh = mesh_index;
    info.primitive = prim_index;
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(where + ".mode: " + std::to_string(mode) + " is not a valid primitive mode");
    info.mode = static_cast<PrimitiveMode>(mode);
    info.material = prim.material;
    info.morph_targets = static_cast<std::uint32_t>(prim.targets.size());
    if (prim.material >= static_cast<int>(model.materials.size()) || prim.material < -1)
        fail(where + ".material: index " + std::to_string(prim.material) +
             " out of range (file has " + std::to_string(model.materials.size()) + " materials)");

    const auto pos_it = prim.attributes.find("POSITION");
    for (const auto& [name, accessor] : prim.attributes) {
        accessor_count(model, accessor, where + ".attributes." + name); // validates the index
        info.file_attributes.push_back(name);
    }
    auto finish_skipped = [&](std::string reason) {
        ctx.warn(where + ": " + reason);
        info.skipped_reason = std::move(reason);
        scene.mesh_primitives[mesh_index].push_back(-1);
        scene.primitives.push_back(std::move(info));
    };
    if (pos_it == prim.attributes.end()) {
        ++scene.counts.primitives;
        return finish_skipped("no POSITION attribute; primitive not drawn");
    }
    const std::uint32_t vertex_count =
        accessor_count(model, pos_it->second, where + ".attributes.POSITION");
    // Positions are decoded (and their data range-checked) before anything is sized
    // by vertex_count: a count is only believed once the file's bytes back it.
    const std::string pos_path = where + ".attributes.POSITION";
    std::uint32_t pos_components = 0;
    const std::vector<float> positions =
        read_accessor_floats(model, pos_it->second, {3}, pos_components, pos_path);
    ctx.check_declared_range(pos_it->second, positions, 3, pos_path);
    info.vertices = vertex_count;
    scene.counts.vertices += vertex_count;
    ++scene.counts.primitives;

    std::vector<std::uint32_t> source_indices;
    if (prim.indices >= 0) {
        source_indices = read_accessor_indices(model, prim.indices, where + ".indices");
        for (std::size_t i = 0; i < source_indices.size(); ++i)
            if (source_indices[i] >= vertex_count)
                fail(where + ".indices (accessors[" + std::to_string(prim.indices) + "])[" +
                     std::to_string(i) + "] = " + std::to_string(source_indices[i]) +
                     " is beyond the vertex count " + std::to_string(vertex_count));
        info.indices = static_cast<std::uint32_t>(source_indices.size());
    } else {
        source_indices.resize(vertex_count);
        for (std::uint32_t i = 0; i < vertex_count; ++i) source_indices[i] = i;
    }
    Mesh mesh;
    mesh.group_id = mesh_index;
    mesh.primitive_index = prim_index;
    mesh.name = model.meshes[mesh_index].name + "#" + std::to_string(prim_index);
    mesh.source_mode = info.mode;
    const Topology topology = mesh.topology();
    mesh.indices = topology == Topology::Triangles
                       ? to_triangle_list(info.mode, source_indices)
                       : to_line_or_point_list(info.mode, source_indices);
    if (mode == TINYGLTF_MODE_TRIANGLES && source_indices.size() % 3 != 0)
        ctx.warn(where + ": " + std::to_string(source_indices.size() % 3) +
                 " trailing indices ignored (count not a multiple of 3)");
    if (info.mode == PrimitiveMode::Lines && source_indices.size() % 2 != 0)
        ctx.warn(where + ": 1 trailing index ignored (LINES count not a multiple of 2)");
    info.triangles = mesh.triangle_count();
    if (topology == Topology::Lines) info.segments = mesh.element_count();
    if (topology == Topology::Points) info.points = mesh.element_count();
    mesh.source_vertex_count = vertex_count;
    mesh.source_triangle_count = info.triangles;
    scene.counts.triangles += info.triangles;
    if (vertex_count == 0 || mesh.element_count() == 0)
        return finish_skipped("empty primitive (" + std::to_string(vertex_count) + " vertices, 0 " +
                              std::string(to_string(topology)) + "); not drawn");

    mesh.vertices.resize(vertex_count);
    for (std::uint32_t i = 0; i < vertex_count; ++i)
        mesh.vertices[i].position = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    mesh.provenance[static_cast<std::size_t>(VertexAttribute::Position)] = Provenance::Authored;
    mesh.sources[static_cast<std::size_t>(VertexAttribute::Position)] =
        describe_accessor(model, pos_it->second);
    for (std::uint32_t i = 0; i < vertex_count; ++i)
        if (!core::is_finite(mesh.vertices[i].position))
            fail(where + ".attributes.POSITION[" + std::to_string(i) +
                 "] is not finite (NaN or Inf)");
    read_vec_attribute(ctx, prim, "NORMAL", {3}, vertex_count, where, mesh, VertexAttribute::Normal,
                       [&](std::uint32_t i, const float* v, std::uint32_t) {
                           mesh.vertices[i].normal = {v[0], v[1], v[2]};
                       });
    read_vec_attribute(ctx, prim, "TANGENT", {4}, vertex_count, where, mesh,
                       VertexAttribute::Tangent,
                       [&](std::uint32_t i, const float* v, std::uint32_t) {
                           mesh.vertices[i].tangent = {v[0], v[1], v[2], v[3]};
                       });
    read_vec_attribute(ctx, prim, "TEXCOORD_0", {2}, vertex_count, where, mesh,
                       VertexAttribute::TexCoord0,
                       [&](std::uint32_t i, const float* v, std::uint32_t) {
                           mesh.vertices[i].uv0 = {v[0], v[1]};
                       });
    read_vec_attribute(ctx, prim, "TEXCOORD_1", {2}, vertex_count, where, mesh,
                       VertexAttribute::TexCoord1,
                       [&](std::uint32_t i, const float* v, std::uint32_t) {
                           mesh.vertices[i].uv1 = {v[0], v[1]};
                       });
    if (prim.attributes.count("COLOR_0")) mesh.colors.resize(vertex_count);
    read_vec_attribute(ctx, prim, "COLOR_0", {3, 4}, vertex_count, where, mesh,
                       VertexAttribute::Color0,
                       [&](std::uint32_t i, const float* v, std::uint32_t n) {
                           mesh.colors[i] = {v[0], v[1], v[2], n == 4 ? v[3] : 1.0f};
                       });
    if (prim.indices >= 0) mesh.index_source = describe_accessor(model, prim.indices);

    if (topology != Topology::Triangles) {
        // Lines and points are drawn unlit: no faces to take a normal from.
    } else if (mesh.provenance_of(VertexAttribute::Normal) == Provenance::Defaulted) {
        const std::uint32_t degenerate = unweld_with_flat_normals(mesh);
        mesh.provenance[static_cast<std::size_t>(VertexAttribute::Normal)] = Provenance::Generated;
        if (degenerate)
            ctx.warn(where + ": " + std::to_string(degenerate) +
                     " degenerate triangles have no face normal; +Z used");
    } else {
        std::uint32_t renormalised = 0, invalid = 0;
        ImportContext::Renormalised& total = ctx.renormalised;
        for (auto& v : mesh.vertices) {
            const float len = glm::length(v.normal);
            if (!std::isfinite(len) || len == 0.0f)
                ++invalid;
            else if (std::abs(len - 1.0f) > 1e-3f) {
                v.normal /= len;
                ++renormalised;
                if (std::abs(len - 1.0f) > std::abs(total.worst_length - 1.0f)) {
                    total.worst_length = len;
                    total.worst_where = where;
                }
            }
        }
        total.normals += renormalised;
        total.primitives += renormalised ? 1 : 0;
        if (invalid) {
            repair_invalid_normals(mesh);
            ctx.warn(where + ": " + std::to_string(invalid) +
                     " zero-length or NaN normals replaced by their faces' normal (a NaN "
                     "normal shades black)");
        }
    }

    mesh.material_id =
        prim.material >= 0 ? static_cast<std::uint32_t>(prim.material) : ctx.default_material_id();
    if (prim.material < 0) ctx.warn(where + ": no material; using the default material");
    for (const auto& v : mesh.vertices) mesh.local_bounds.expand(v.position);

    info.motion = import_primitive_motion(ctx, prim, where, positions, info);
    info.engine_mesh = static_cast<std::int32_t>(scene.meshes.size());
    scene.mesh_primitives[mesh_index].push_back(info.engine_mesh);
    scene.meshes.push_back(std::move(mesh));
    scene.primitives.push_back(std::move(info));
}

} // namespace

void ImportContext::check_declared_range(int index, const std::vector<float>& values,
                                         std::uint32_t components, const std::string& where) {
    if (!range_checked.insert(index).second) return;
    if (index >= 0 && static_cast<std::size_t>(index) < bounds_hold.size() &&
        bounds_hold[static_cast<std::size_t>(index)])
        return; // the validator's data pass read these values and found them inside
    if (auto v = detail::check_declared_range(model, index, values, components, where)) {
        warn(describe_range_violation(*v));
        scene.range_violations.push_back(std::move(*v));
    }
}

void import_meshes(ImportContext& ctx) {
    const auto& model = ctx.model;
    ctx.scene.counts.meshes = model.meshes.size();
    ctx.scene.mesh_primitives.resize(model.meshes.size());
    Scene& scene = ctx.scene;
    for (std::uint32_t m = 0; m < model.meshes.size(); ++m)
        for (std::uint32_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            // A primitive that cannot be read is skipped and named; the rest loads.
            const SourceCounts counts = scene.counts;
            const std::size_t meshes = scene.meshes.size(), primitives = scene.primitives.size(),
                              motions = scene.motions.size(),
                              slots = scene.mesh_primitives[m].size();
            try {
                if (const auto it = ctx.undecodable.find({m, p}); it != ctx.undecodable.end())
                    fail(it->second);
                import_primitive(ctx, m, p);
            } catch (const ImportError& e) {
                scene.counts = counts;
                ++scene.counts.primitives;
                scene.meshes.resize(meshes);
                scene.primitives.resize(primitives);
                scene.motions.resize(motions);
                scene.mesh_primitives[m].resize(slots);
                PrimitiveInfo info;
                info.mesh = m;
                info.primitive = p;
                info.skipped_reason = e.what();
                scene.mesh_primitives[m].push_back(-1);
                scene.primitives.push_back(std::move(info));
                ctx.skip("SHERPA_PRIMITIVE_SKIPPED",
                         std::string(e.what()) + " (primitive skipped)");
            }
        }
    if (const ImportContext::Renormalised& r = ctx.renormalised; r.normals) {
        char worst[32];
        std::snprintf(worst, sizeof worst, "%.4g", double(r.worst_length));
        ctx.warn(std::to_string(r.normals) + " non-unit normals renormalised in " +
                 std::to_string(r.primitives) + " primitive(s); worst length " + worst + " (" +
                 r.worst_where + ")");
    }
}

} // namespace sherpa::scene::detail
