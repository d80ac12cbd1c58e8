#include "tangent_error.h"

#include <cmath>
#include <limits>

#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/tangent_compare.h>

namespace sherpa::editor {

TangentErrors tangent_errors(const scene::Mesh& mesh, std::uint32_t tex_coord) {
    TangentErrors out;
    out.degrees.assign(mesh.vertices.size(), std::numeric_limits<float>::quiet_NaN());
    if (mesh.indices.empty()) return out;
    const scene::MeshTangentInput input =
        scene::tangent_input_of(mesh, tex_coord > 1 ? 0 : tex_coord);
    std::vector<glm::vec4> regenerated(mesh.indices.size());
    scene::generate_corner_tangents(input.view(mesh), scene::TangentMethod::MikkTSpace,
                                    regenerated);
    double sum = 0.0;
    std::uint64_t counted = 0;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const glm::vec4& authored = mesh.vertices[mesh.indices[c]].tangent;
        const double angle = scene::tangent_angle_degrees(authored, regenerated[c]);
        if ((authored.w < 0.0f) != (regenerated[c].w < 0.0f)) ++out.flips;
        if (!std::isfinite(angle)) continue;
        float& v = out.degrees[mesh.indices[c]];
        if (std::isnan(v) || angle > v) v = static_cast<float>(angle);
        sum += angle;
        ++counted;
        if (angle > out.max) out.max = angle;
    }
    out.mean = counted ? sum / static_cast<double>(counted) : 0.0;
    return out;
}

} // namespace sherpa::editor
