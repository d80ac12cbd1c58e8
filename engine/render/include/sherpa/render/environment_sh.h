#pragma once
// Irradiance as 9 spherical-harmonic coefficients (bands 0-2; Ramamoorthi and Hanrahan,
// "An Efficient Representation for Irradiance Environment Maps", 2001): the
// environment's radiance projected on the real SH basis, each band convolved with the
// clamped cosine. The raster reads them instead of the irradiance cube with
// EnvironmentOptions::irradiance = IrradianceMode::Sh9 (shaders/include/ibl.glsl).
//
// Exact for radiance that is constant or linear in the direction; anything sharper
// loses its bands above 2 (about 1% of a clamped cosine's energy, more for small bright
// lights) and rings where the radiance changes abruptly.
#include <array>

#include <glm/glm.hpp>

#include <sherpa/render/environment.h>

namespace sherpa::render {

// Coefficient k of band l, order m is k = l (l + 1) + m: (0,0), (1,-1), (1,0), (1,1),
// (2,-2), (2,-1), (2,0), (2,1), (2,2). Directions in the image's own frame (+Y up).
using Sh9 = std::array<glm::vec3, 9>;

// The real SH basis at unit direction `d` (constants included).
std::array<float, 9> sh9_basis(glm::vec3 d);

// Radiance coefficients L_lm of an equirectangular image (environment.h's convention),
// integrated over each texel's exact solid angle. Non-finite texels count as 0.
// An invalid image gives zeros.
Sh9 project_sh9(const EnvironmentImage& image);

// The coefficients that give the cosine-weighted mean radiance (irradiance / pi, what
// the irradiance cube holds) as sum_k c_k Y_k(n): L_lm times A_l / pi with the clamped
// cosine's A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
Sh9 irradiance_sh9(const Sh9& radiance);

// sum_k c_k Y_k(n): with irradiance_sh9()'s coefficients, irradiance / pi along n.
glm::vec3 evaluate_sh9(const Sh9& coefficients, glm::vec3 n);

} // namespace sherpa::render
