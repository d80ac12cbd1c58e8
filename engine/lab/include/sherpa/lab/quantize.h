#pragma once
// Vertex quantization as KHR_mesh_quantization stores it (what gltfpack writes): pure
// functions over spans, used by the Lab's mesh-compression family.
//
// Positions: unsigned integers of `bits` (1..16) on one uniform grid over the mesh's
// bounds (offset = the bounds' minimum, step = the largest extent / (2^bits - 1)); the
// dequantization (offset, uniform scale) goes into the node transform, so the grid is
// uniform and angles are kept. UVs: unsigned normalized integers of `bits` (1..16)
// over their own range per axis (the offset and scale go into KHR_texture_transform).
// Normals and tangents: signed normalized integers of `bits` (2..16) per component
// (not octahedral), decoded as c / (2^(bits-1) - 1) and renormalized, as a shader does.
//
// Contracts common to all: `codes` and `out` have the size of the input; non-finite
// input components are coded as 0 (the grid's minimum, or 0 for snorm) and counted in
// the return value, never propagated; the grids are made from finite values only.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace sherpa::lab {

inline constexpr int kMinUnormBits = 1, kMinSnormBits = 2, kMaxQuantBits = 16;

// code = round((p - offset) / step) per axis, clamped to 0..2^bits-1. step is 0 when
// all finite positions coincide (every code 0, decoded exactly); offset and step are
// double so that coordinates near the float range (extent up to 2 * FLT_MAX) work.
struct PositionGrid {
    glm::dvec3 offset{0.0};
    double step = 0.0;
    glm::dvec3 max{0.0}; // the bounds' maximum: decoded values are clamped to it
    int bits = 0;
};
// Per-axis version for UVs (KHR_texture_transform scales each axis).
struct UvGrid {
    glm::dvec2 offset{0.0}, step{0.0}, max{0.0};
    int bits = 0;
};

enum class GridStatus : std::uint8_t {
    Ok,
    BitsOutOfRange, // bits outside kMinUnormBits..kMaxQuantBits
    NoFiniteValue,  // empty input, or no element whose components are all finite
};
const char* to_string(GridStatus s);

// The grid over the elements whose components are all finite.
GridStatus position_grid(std::span<const glm::vec3> positions, int bits, PositionGrid& out);
GridStatus uv_grid(std::span<const glm::vec2> uvs, int bits, UvGrid& out);

// Return the number of elements with a non-finite component (coded as 0 on all axes).
// A valid grid is required (from position_grid / uv_grid returning Ok).
std::size_t quantize_positions(std::span<const glm::vec3> in, const PositionGrid& grid,
                               std::span<glm::u16vec3> codes);
std::size_t quantize_uvs(std::span<const glm::vec2> in, const UvGrid& grid,
                         std::span<glm::u16vec2> codes);
// offset + code * step, rounded to float and clamped to the grid's bounds: the error
// per axis is at most step / 2 plus half a float ulp of the decoded value.
void dequantize_positions(std::span<const glm::u16vec3> codes, const PositionGrid& grid,
                          std::span<glm::vec3> out);
void dequantize_uvs(std::span<const glm::u16vec2> codes, const UvGrid& grid,
                    std::span<glm::vec2> out);

// Signed normalized components: c = round(clamp(v, -1, 1) * (2^(bits-1) - 1)).
// Returns the number of non-finite components (coded 0), or -1 when bits is outside
// kMinSnormBits..kMaxQuantBits (nothing written).
long quantize_snorm(std::span<const float> in, int bits, std::span<std::int16_t> codes);
// c / (2^(bits-1) - 1), clamped to -1 (as glTF decodes normalized integers). bits must
// be valid for quantize_snorm.
void dequantize_snorm(std::span<const std::int16_t> codes, int bits, std::span<float> out);

// Bytes per vertex of one attribute stream as KHR_mesh_quantization lays it out
// (every element starts on a 4-byte boundary): bits 0 means 32-bit float. Positions,
// normals: 3 components; tangents: 4; uvs: 2. 8 bits or fewer: one byte per component,
// else two.
std::uint32_t stream_stride(int components, int bits);

} // namespace sherpa::lab
