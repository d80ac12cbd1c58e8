#pragma once
// Tangents on engine meshes: applying per-corner tangents (splitting vertices where the
// corners of one vertex disagree) and the glTF rule for when to generate them.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <sherpa/core/progress.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/tangents.h>

namespace sherpa::scene {

// Writes corner_tangents (one per index, glTF triangle order) into mesh.vertices. A
// vertex whose corners carry different tangents is duplicated once per further distinct
// tangent (with its COLOR_0), and those corners' indices are redirected to the copies,
// so every corner keeps its exact tangent. Returns the number of vertices added.
// Contract: corner_tangents.size() == mesh.indices.size() (else std::invalid_argument).
std::uint32_t apply_corner_tangents(Mesh& mesh, std::span<const glm::vec4> corner_tangents);

// The per-corner inputs for tangent generation from a mesh, using uv set `tex_coord`
// (0 or 1; Vertex holds no other set). Spans of the result point into its vectors.
struct MeshTangentInput {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    TangentInput view(const Mesh& mesh) const;
};
MeshTangentInput tangent_input_of(const Mesh& mesh, std::uint32_t tex_coord);

// The uv set the mesh's normal texture samples (its texCoord, possibly > 1), 0 without
// one: the set tangents are made from.
std::uint32_t normal_uv_set(const Scene& scene, const Mesh& mesh);

struct MeshTangentReport {
    bool generated = false; // tangents were computed and written
    std::string reason;     // why not, or what was done ("regenerated", "normal texture ...")
    std::uint32_t tex_coord = 0;
    std::uint32_t split_vertices = 0;
    TangentStats stats;
};

// Generates tangents with `method` from uv set `tex_coord`, applies them (splitting as
// above) and marks the tangent attribute Generated. tex_coord > 1 uses uv0 and says so.
MeshTangentReport generate_mesh_tangents(Mesh& mesh, std::uint32_t tex_coord, TangentMethod method,
                                         TangentWorkspace* workspace = nullptr);

struct SceneTangentOptions {
    TangentMethod method = TangentMethod::MikkTSpace;
    // false: the glTF rule (tangents only where TANGENT is absent and the material has a
    // normal texture). true: every triangle mesh, replacing authored tangents too.
    bool regenerate = false;
    // Meshes done of meshes in the scene, called on OpenMP worker threads as each
    // mesh finishes; must be thread-safe.
    core::ProgressCallback progress;
    // Polled before each mesh: once cancelled the remaining meshes are skipped
    // (the scene is then half done and must be discarded).
    const core::CancelToken* cancel = nullptr;
};

struct SceneTangentReport {
    std::vector<MeshTangentReport> meshes; // parallel to Scene::meshes
    std::uint32_t generated_meshes = 0;
    std::uint64_t split_vertices = 0;
    TangentStats stats; // summed over generated meshes
};

// Applies the options to every mesh of the scene, in parallel across meshes (OpenMP,
// one workspace per thread).
SceneTangentReport generate_scene_tangents(Scene& scene, const SceneTangentOptions& options);
// Appends the report's failures and fallback counts to scene.warnings.
void add_tangent_warnings(Scene& scene, const SceneTangentReport& report);

} // namespace sherpa::scene
