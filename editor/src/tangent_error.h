#pragma once
// Authored-vs-regenerated tangent error per vertex: MikkTSpace is run on the
// mesh's own positions/normals/uvs and each corner's result is compared with the
// tangent the vertex carries; a vertex keeps the largest angle over its corners.
#include <vector>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

struct TangentErrors {
    std::vector<float> degrees; // per vertex; NaN where no corner references it
    double max = 0.0, mean = 0.0;
    std::uint64_t flips = 0; // corners whose handedness differs
};

// `tex_coord` is the uv set the material's normal texture samples (0 or 1).
TangentErrors tangent_errors(const scene::Mesh& mesh, std::uint32_t tex_coord);

} // namespace sherpa::editor
