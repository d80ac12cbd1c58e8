#pragma once
// Small synthetic scenes with known answers for the Lab's families.
#include <sherpa/scene/scene.h>

namespace sherpa::test {

// Two unit quads side by side in the XY plane (x 0..1 and 1..2), the second's u
// mirrored about x = 1, sharing the two vertices of the seam column; normals +Z.
// Exact MikkTSpace gives the left quad (+1,0,0,+1) and the right one (-1,0,0,-1);
// welded keeps the last corner written at each seam vertex (the right quad's), so
// the left quad's 3 corners on the seam differ.
scene::Mesh mirrored_strip();

// An n x n grid of vertices over x 0..3, y 0..1 on a wavy surface (z up to 0.5),
// normals tilted in every direction, uv0 over 0..2 x 0..1, triangles between them.
scene::Mesh wavy_grid(int n);

// A scene of the given meshes, each drawn once with one default material.
scene::Scene scene_of(std::vector<scene::Mesh> meshes);

} // namespace sherpa::test
