#pragma once
// BC5 normal maps store a tangent-space normal's x and y only; z comes back from
// unit length. This is the one C++ definition (quality metrics, thumbnails); the
// shaders' only copy is mapped_normal() in shaders/include/material_sampling.glsl.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

namespace sherpa::tex {

// z >= 0 of the unit normal with x, y in -1..1; 0 where x^2 + y^2 > 1 (block
// compression can push a texel outside the unit disc).
template <typename T> T bc5_normal_z(T x, T y) {
    return std::sqrt(std::max(T(0), T(1) - x * x - y * y));
}

// Decoded BC5 texels (RGBA8, R = x, G = y as v / 127.5 - 1) get z in B, encoded the
// same way, so they display like an RGB normal map. `rgba.size()` must be a multiple of 4.
void rebuild_bc5_z(std::span<std::uint8_t> rgba);

} // namespace sherpa::tex
