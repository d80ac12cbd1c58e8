// Tangents on engine meshes: per-corner results written into vertices with splitting,
// and the glTF rule deciding which meshes get generated tangents.
#include <cstring>
#include <stdexcept>

#include <sherpa/scene/mesh_tangents.h>

namespace sherpa {
namespace {

constexpr std::uint32_t kNone = ~0u;

bool same_bits(const glm::vec4& a, const glm::vec4& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

std::size_t attribute_slot(VertexAttribute a) {
    return static_cast<std::size_t>(a);
}

} // namespace

std::uint32_t apply_corner_tangents(Mesh& mesh, std::span<const glm::vec4> corner_tangents) {
    if (corner_tangents.size() != mesh.indices.size())
        throw std::invalid_argument("apply_corner_tangents: one tangent per index expected");
    const std::size_t original_count = mesh.vertices.size();
    // For each vertex, the chain of its copies: next_copy[v] is the next vertex carrying
    // the same attributes with another tangent. written[v] says whether v holds a tangent
    // of this pass yet.
    std::vector<std::uint32_t> next_copy(original_count, kNone);
    std::vector<std::uint8_t> written(original_count, 0);
    const bool has_colors = mesh.colors.size() == original_count;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const glm::vec4& tangent = corner_tangents[c];
        std::uint32_t v = mesh.indices[c];
        if (!written[v]) {
            mesh.vertices[v].tangent = tangent;
            written[v] = 1;
            continue;
        }
        // Walk the copies for one holding this exact tangent; append a copy otherwise.
        std::uint32_t last = v;
        while (v != kNone && !same_bits(mesh.vertices[v].tangent, tangent)) {
            last = v;
            v = next_copy[v];
        }
        if (v == kNone) {
            v = static_cast<std::uint32_t>(mesh.vertices.size());
            Vertex copy = mesh.vertices[last];
            copy.tangent = tangent;
            mesh.vertices.push_back(copy);
            if (has_colors) mesh.colors.push_back(mesh.colors[last]);
            next_copy.push_back(kNone);
            written.push_back(1);
            next_copy[last] = v;
        }
        mesh.indices[c] = v;
    }
    return static_cast<std::uint32_t>(mesh.vertices.size() - original_count);
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

MeshTangentReport generate_mesh_tangents(Mesh& mesh, std::uint32_t tex_coord,
                                         TangentMethod method) {
    MeshTangentReport report;
    report.tex_coord = tex_coord > 1 ? 0 : tex_coord;
    if (tex_coord > 1)
        report.reason = "TEXCOORD_" + std::to_string(tex_coord) + " is not kept; used TEXCOORD_0";
    const MeshTangentInput input = tangent_input_of(mesh, report.tex_coord);
    std::vector<glm::vec4> corners(mesh.indices.size());
    report.stats = generate_corner_tangents(input.view(mesh), method, corners);
    report.split_vertices = apply_corner_tangents(mesh, corners);
    mesh.provenance[attribute_slot(VertexAttribute::Tangent)] = Provenance::Generated;
    report.generated = true;
    return report;
}

SceneTangentReport generate_scene_tangents(Scene& scene, const SceneTangentOptions& options) {
    SceneTangentReport report;
    report.meshes.resize(scene.meshes.size());
    const auto mesh_count = static_cast<std::int64_t>(scene.meshes.size());
    // Meshes are independent; dynamic scheduling because their sizes vary by orders of
    // magnitude. Exceptions cannot cross the OpenMP region, so they become reasons.
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t i = 0; i < mesh_count; ++i) {
        Mesh& mesh = scene.meshes[static_cast<std::size_t>(i)];
        MeshTangentReport& out = report.meshes[static_cast<std::size_t>(i)];
        const bool authored = mesh.provenance_of(VertexAttribute::Tangent) == Provenance::Authored;
        const MaterialInstance* material = mesh.material_id < scene.materials.size()
                                               ? &scene.materials[mesh.material_id]
                                               : nullptr;
        const bool normal_texture = material && material->normal.present();
        if (!options.regenerate && authored) {
            out.reason = "authored TANGENT kept";
            continue;
        }
        if (!options.regenerate && !normal_texture) {
            out.reason = "no normal texture: tangents not needed";
            continue;
        }
        const std::uint32_t set = normal_texture ? material->normal.tex_coord : 0;
        try {
            out = generate_mesh_tangents(mesh, set, options.method);
            if (out.reason.empty()) out.reason = authored ? "regenerated" : "generated";
        } catch (const std::exception& e) {
            out.reason = std::string("tangent generation failed: ") + e.what();
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

} // namespace sherpa
