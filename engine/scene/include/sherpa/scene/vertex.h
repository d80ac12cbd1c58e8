#pragma once
// The canonical CPU vertex and per-attribute provenance.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <glm/glm.hpp>

namespace sherpa::scene {

// Himalaya's unified 56-byte vertex. The GPU layer uploads only the streams a scene's
// materials use (see UsageReport); this is the CPU-side interchange format.
struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv0{0.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; // xyz tangent, w handedness (+1/-1)
    glm::vec2 uv1{0.0f};
};
static_assert(sizeof(Vertex) == 56);
static_assert(offsetof(Vertex, position) == 0);
static_assert(offsetof(Vertex, normal) == 12);
static_assert(offsetof(Vertex, uv0) == 24);
static_assert(offsetof(Vertex, tangent) == 32);
static_assert(offsetof(Vertex, uv1) == 48);

// Where an attribute's values came from.
enum class Provenance : std::uint8_t {
    Authored,  // read from the file
    Generated, // computed by Sherpa (flat normals, MikkTSpace tangents, ...)
    Defaulted, // absent in the file; a constant default stands in
};

enum class VertexAttribute : std::uint8_t {
    Position,
    Normal,
    Tangent,
    TexCoord0,
    TexCoord1,
    Color0
};
inline constexpr std::size_t kVertexAttributeCount = 6;
inline constexpr std::array<VertexAttribute, kVertexAttributeCount> kAllVertexAttributes{
    VertexAttribute::Position,  VertexAttribute::Normal,    VertexAttribute::Tangent,
    VertexAttribute::TexCoord0, VertexAttribute::TexCoord1, VertexAttribute::Color0};

// glTF attribute semantic, e.g. "TEXCOORD_0".
std::string_view gltf_name(VertexAttribute a);
std::string_view to_string(Provenance p);

// Bytes per vertex of one attribute stream when stored as 32-bit floats on the GPU.
std::uint32_t stream_stride(VertexAttribute a);

} // namespace sherpa::scene
