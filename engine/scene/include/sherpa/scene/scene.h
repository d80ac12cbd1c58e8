#pragma once
// The engine's flat, render-ready scene model. Built by the glTF importer or the
// built-in scene generators; knows nothing about files or GPUs.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/scene/material.h>
#include <sherpa/scene/material_variants.h>
#include <sherpa/scene/motion.h>
#include <sherpa/scene/texture_records.h>
#include <sherpa/scene/validation.h>
#include <sherpa/scene/vertex.h>

namespace sherpa::scene {

// glTF primitive topology (values equal glTF's `mode`).
enum class PrimitiveMode : std::uint8_t {
    Points = 0,
    Lines = 1,
    LineLoop = 2,
    LineStrip = 3,
    Triangles = 4,
    TriangleStrip = 5,
    TriangleFan = 6,
};
std::string_view to_string(PrimitiveMode m);

// What the engine draws a primitive as: strips, fans and loops become lists.
enum class Topology : std::uint8_t { Triangles, Lines, Points };
constexpr Topology topology_of(PrimitiveMode m) {
    return m == PrimitiveMode::Points                                   ? Topology::Points
           : m >= PrimitiveMode::Lines && m <= PrimitiveMode::LineStrip ? Topology::Lines
                                                                        : Topology::Triangles;
}
// Indices per element of the topology: 3, 2, 1.
constexpr std::uint32_t indices_per_element(Topology t) {
    return t == Topology::Triangles ? 3u : t == Topology::Lines ? 2u : 1u;
}
std::string_view to_string(Topology t); // "triangles", "lines", "points"

// Where an attribute came from in the file (for the mesh/attribute dock).
struct AccessorSource {
    std::int32_t accessor = -1;
    std::int32_t component_type = 0; // glTF componentType (5120..5126)
    bool normalized = false;
    std::uint32_t components = 0; // 1 (SCALAR) .. 4 (VEC4)
    std::uint32_t count = 0;
    std::int32_t buffer_view = -1;
    std::uint32_t byte_stride = 0; // effective stride in bytes (0 without bufferView)
    bool sparse = false;
    std::uint32_t sparse_count = 0;
    std::vector<double> min, max; // as declared in the file (may be empty)
};

// One engine mesh per drawable glTF primitive: triangles, lines or points.
struct Mesh {
    std::uint32_t group_id = 0;        // source glTF mesh index
    std::uint32_t primitive_index = 0; // index within the glTF mesh
    std::string name;
    PrimitiveMode source_mode = PrimitiveMode::Triangles;
    std::uint32_t material_id = 0; // index into Scene::materials
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices; // triangle, line or point list (topology())
    std::vector<glm::vec4> colors;      // COLOR_0 (RGBA, linear) or empty
    std::array<Provenance, kVertexAttributeCount> provenance{};
    std::array<std::optional<AccessorSource>, kVertexAttributeCount> sources;
    std::optional<AccessorSource> index_source;
    core::Aabb local_bounds;
    // Counted the glTF way, before unwelding/splitting.
    std::uint32_t source_vertex_count = 0;
    std::uint32_t source_triangle_count = 0;
    bool unwelded = false; // vertices were split per corner for flat normals
    // Per vertex: its index in the file's POSITION accessor, where unwelding or
    // tangent splitting changed the vertices; empty while vertex i is source vertex i.
    // Skinning and morph data (PrimitiveMotion) are in source order: this maps them.
    std::vector<std::uint32_t> source_vertex;

    Provenance provenance_of(VertexAttribute a) const {
        return provenance[static_cast<std::size_t>(a)];
    }
    Topology topology() const { return topology_of(source_mode); }
    // Triangles of a triangle mesh, 0 for lines and points.
    std::uint32_t triangle_count() const {
        return topology() == Topology::Triangles ? static_cast<std::uint32_t>(indices.size() / 3)
                                                 : 0u;
    }
    // Triangles, line segments or points: what one draw of the mesh rasterizes.
    std::uint32_t element_count() const {
        return static_cast<std::uint32_t>(indices.size() / indices_per_element(topology()));
    }
};

// Every glTF primitive, triangle or not, as the file describes it.
// How a primitive's data was compressed in the file (EXT/KHR_meshopt_compression),
// summed over the compressed bufferViews its accessors read.
struct PrimitiveCompression {
    std::string codec; // the extension's name
    std::string modes; // e.g. "ATTRIBUTES/OCTAHEDRAL, ATTRIBUTES, TRIANGLES"
    std::uint64_t encoded_bytes = 0, decoded_bytes = 0;
    double decode_ms = 0.0;
};

struct PrimitiveInfo {
    std::uint32_t mesh = 0, primitive = 0;
    PrimitiveMode mode = PrimitiveMode::Triangles;
    std::uint32_t vertices = 0;                      // POSITION count
    std::uint32_t indices = 0;                       // index accessor count (0 if non-indexed)
    std::uint32_t triangles = 0;                     // after strip/fan conversion
    std::uint32_t segments = 0;                      // lines: after strip/loop conversion
    std::uint32_t points = 0;                        // points: one per index (or vertex)
    std::int32_t material = -1;                      // glTF material index (-1: none)
    std::int32_t engine_mesh = -1;                   // index into Scene::meshes, -1 if skipped
    std::string skipped_reason;                      // why no engine mesh was made
    std::vector<std::string> file_attributes;        // attribute semantics the file gives
    std::optional<PrimitiveCompression> compression; // empty: stored uncompressed
    std::int32_t motion = -1;                        // index into Scene::motions, -1: static
    std::uint32_t morph_targets = 0;                 // as the file gives them
};

// One row of a node's EXT_mesh_gpu_instancing attributes: an instance of the node's
// mesh at node world x T x R x S.
struct InstanceRow {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // unit length (normalised on import)
    glm::vec3 scale{1.0f};
    std::uint32_t file_row = 0; // its index in the file's accessors
    glm::mat4 matrix() const;   // T * R * S
};

// A node's EXT_mesh_gpu_instancing: the rows that are drawn (non-finite ones and
// those past kMaxGpuInstanceRows are not), and what the file states.
struct NodeInstancing {
    std::vector<InstanceRow> rows;
    std::uint32_t file_rows = 0; // the count of the attribute accessors (the smallest)
    std::int32_t translation = -1, rotation = -1, scale = -1; // accessor indices, -1: absent
    std::vector<std::string> custom_attributes;               // _ID, ...: read, not drawn
};
// At most this many instances (rows x drawable primitives) come from
// EXT_mesh_gpu_instancing per file; rows past it are not drawn, with a warning.
inline constexpr std::uint64_t kMaxGpuInstanceRows = std::uint64_t{1} << 20;

struct Node {
    std::string name;
    std::int32_t parent = -1;
    std::vector<std::uint32_t> children;
    bool has_matrix = false;
    glm::mat4 matrix{1.0f};
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::int32_t mesh = -1, camera = -1, light = -1, skin = -1;
    // KHR_node_visibility: false hides the node and its subtree (the renderer's
    // visibility; KHR_animation_pointer may animate it).
    bool visible = true;
    std::vector<float> weights; // morph weights: the node's, else its mesh's, else zeros
    std::optional<NodeInstancing> instancing; // EXT_mesh_gpu_instancing: one instance per row
    glm::mat4 local_transform() const;
};

enum class LightType : std::uint8_t { Directional, Point, Spot };
struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f; // 0 = infinite
    float inner_cone = 0.0f, outer_cone = 0.785398163f;
};

enum class CameraType : std::uint8_t { Perspective, Orthographic };
struct Camera {
    std::string name;
    CameraType type = CameraType::Perspective;
    float yfov = 0.8f, aspect = 0.0f; // aspect 0: use the viewport's
    float znear = 0.05f, zfar = 0.0f; // zfar 0: infinite (perspective)
    float xmag = 1.0f, ymag = 1.0f;
};

// A light or camera placed by a node of the displayed scene.
struct PlacedLight {
    std::uint32_t light = 0, node = 0;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // world-space, unit: where the light points
};
struct PlacedCamera {
    std::uint32_t camera = 0, node = 0;
    glm::mat4 world{1.0f}; // camera-to-world; looks down -Z, up +Y
};

// One drawable: node x primitive of the displayed scene.
struct MeshInstance {
    std::uint32_t mesh_id = 0;
    std::uint32_t material_id = 0;
    std::uint32_t node_id = 0;
    std::int32_t row = -1; // its node's EXT_mesh_gpu_instancing row (Node::instancing), -1: none
    glm::mat4 world{1.0f}; // node world x the row's T * R * S
    glm::mat4 prev_world{1.0f};
    core::Aabb world_bounds;
};

struct SceneDef {
    std::string name;
    std::vector<std::uint32_t> roots;
};

// Counts as the file states them (before unwelding or splitting).
struct SourceCounts {
    std::uint64_t scenes = 0, nodes = 0, meshes = 0, primitives = 0, materials = 0, textures = 0,
                  images = 0, samplers = 0, lights = 0, cameras = 0, vertices = 0, triangles = 0;
};

// An accessor whose decoded data leaves the min/max the file declares for it. glTF
// requires POSITION min/max (and any declared min/max) to be exact, so this is how
// an inspector finds a corrupt buffer: the data is kept as it is, and reported.
struct AccessorRangeViolation {
    std::int32_t accessor = -1;
    std::string where;                              // JSON path of the first use
    std::vector<double> declared_min, declared_max; // after normalisation, like the data
    std::vector<float> data_min, data_max;
    std::uint32_t elements_outside = 0, elements = 0;
};

struct Scene {
    std::string source; // file path or builtin:... spec
    SourceCounts counts;

    std::vector<SceneDef> scenes;
    std::int32_t displayed_scene = 0;
    std::vector<Node> nodes;
    std::vector<Mesh> meshes;
    std::vector<PrimitiveInfo> primitives;
    // Per glTF mesh: engine mesh id per primitive (-1 where skipped).
    std::vector<std::vector<std::int32_t>> mesh_primitives;
    std::vector<MaterialInstance> materials; // glTF materials, then the default if needed
    MaterialVariants variants;               // KHR_materials_variants (material_variants.h)
    std::vector<TextureRecord> textures;
    std::vector<ImageRecord> images;
    std::vector<SamplerDesc> samplers;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<Skin> skins;
    std::vector<Animation> animations;
    std::vector<PrimitiveMotion> motions;         // only primitives that skin or morph
    std::vector<std::vector<float>> mesh_weights; // per glTF mesh: default morph weights

    // Flattened displayed scene.
    std::vector<MeshInstance> instances;
    std::vector<PlacedLight> placed_lights;
    std::vector<PlacedCamera> placed_cameras;
    std::vector<glm::mat4> node_world;          // identity for nodes outside the displayed scene
    std::vector<std::uint32_t> displayed_nodes; // nodes of the displayed scene, depth-first
    core::Aabb bounds;
    // Nodes that are a stage rather than a subject (the built-in scenes' ground plane):
    // drawn and bounded, but automatic framing leaves them out (framing_bounds()).
    std::vector<std::uint32_t> backdrop_nodes;

    // The file's extensionsUsed / extensionsRequired, as written.
    std::vector<std::string> extensions_used, extensions_required;
    // The importer's own warnings as text, one line each; every one is also in
    // `validation` with a SHERPA_ code and its JSON pointer.
    std::vector<std::string> warnings;
    // Every problem found, with Khronos glTF-Validator codes and JSON pointers.
    ValidationReport validation;
    std::vector<AccessorRangeViolation> range_violations;
    double parse_ms = 0.0, process_ms = 0.0;

    // node x primitive pairs of the displayed scene, drawable or not (points,
    // lines and empty primitives included), as the file states them (an
    // EXT_mesh_gpu_instancing node counts once per row of its accessors).
    std::uint64_t node_primitive_pairs() const;
    // Every attribute of a primitive with its provenance: the engine mesh's six
    // streams as they are now (after tangent generation and the like), plus the
    // file's other attributes (JOINTS_0, ...) as authored.
    std::vector<std::pair<std::string, Provenance>>
    attribute_provenance(const PrimitiveInfo& p) const;
    // Sampler for a texture, the glTF default when it names none.
    SamplerDesc sampler_of(const TextureRecord& t) const;
};

// The instance's EXT_mesh_gpu_instancing row transform (T * R * S), the identity for
// an instance without one: its world is its node's world times this.
glm::mat4 instance_transform(const Scene& scene, const MeshInstance& instance);

// Rebuilds the flattened data (instances, placed lights/cameras, bounds) for
// `scene_index`. Returns false with `error` set if the index is out of range or a
// transform is not finite; the scene is unchanged then. An instance whose world bounds
// overflow the float range (finite transforms times finite positions) is left out, with
// a SHERPA_INSTANCE_SKIPPED warning in `scene.validation` and its text in `warnings`.
bool select_scene(Scene& scene, std::int32_t scene_index, std::string& error);

} // namespace sherpa::scene
