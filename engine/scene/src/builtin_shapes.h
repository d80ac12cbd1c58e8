#pragma once
// Internal: procedural geometry and images for the built-in scenes. Every shape
// is chosen to exercise something users debug: UV seams, mirrored UV islands.
#include <sherpa/scene/scene.h>

namespace sherpa::scene::detail {

// Ground plane in XZ, facing +Y, with `uv_tiles` repeats of the UV square.
Mesh make_plane(float size, std::uint32_t segments, float uv_tiles);
// UV sphere: u wraps once around, so the u = 0/1 column is a UV seam.
Mesh make_uv_sphere(float radius, std::uint32_t segments, std::uint32_t rings);
// Torus whose u runs 0 -> 1 -> 0 around the ring: two mirrored UV islands.
Mesh make_torus(float major_radius, float minor_radius, std::uint32_t segments,
                std::uint32_t sides);
// Box with 24 vertices; the -X, -Y and -Z faces have mirrored (u -> 1 - u) UVs.
Mesh make_box(glm::vec3 half_extent);

// 256x256 tangent-space normal map of hemispherical bumps, RGBA8 (linear).
ImageRecord make_bump_normal_map(std::uint32_t size);
// Checkerboard base colour (sRGB), opaque.
ImageRecord make_checker(std::uint32_t size, std::uint32_t cells);
// Base colour with round holes: alpha 0 outside the discs, for alpha-mask tests.
ImageRecord make_disc_mask(std::uint32_t size, std::uint32_t discs_per_side);

} // namespace sherpa::scene::detail
