#pragma once
// The path tracer's CPU side (docs/path_tracer.md): the environment's sampling
// distribution, made from the equirectangular image at load, and the error estimate of
// an accumulation from its per-pixel sums. Pure functions, tested without a device.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/render/environment.h>

namespace sherpa::render {

// Importance sampling of an environment by luminance (shaders/include/env_sampling.glsl):
// the image box-filtered down to at most `max_width` columns, each texel weighted by its
// luminance times sin(theta) (the solid angle of an equirectangular texel), as a row
// marginal CDF then one conditional CDF per row. Empty (width 0) for an image without
// light (every weight 0 or non-finite): the path tracer then samples the BRDF only.
struct EnvironmentDistribution {
    std::uint32_t width = 0, height = 0;
    // height + 1 values (0 .. 1), then height rows of width + 1 values (0 .. 1).
    std::vector<float> cdf;
    bool empty() const { return width == 0 || height == 0; }
};
inline constexpr std::uint32_t kEnvironmentDistributionWidth = 512;
EnvironmentDistribution
environment_distribution(const EnvironmentImage& image,
                         std::uint32_t max_width = kEnvironmentDistributionWidth);
// Density per solid angle with which the shader draws direction `d` (the environment's
// own frame, unit): the GLSL environment_pdf's twin.
float environment_pdf(const EnvironmentDistribution& dist, glm::vec3 d);

// An accumulation read back: per pixel (top row first) the sums of `samples` samples
// of radiance (rgb) and coverage (a: 0 where the background colour shows), and the sum
// of squared luminance.
struct PathTraceImage {
    std::uint32_t width = 0, height = 0, samples = 0;
    std::vector<float> sums;    // width * height * 4
    std::vector<float> moments; // width * height
};

// The estimated error of the mean image: per pixel the standard error of its mean
// luminance, sqrt(sample variance / n), averaged over the pixels.
struct PathTraceError {
    std::uint32_t samples = 0;
    double mean_luminance = 0.0;      // over every pixel
    double mean_standard_error = 0.0; // mean over pixels of the standard error
    double rms_standard_error = 0.0;
    // mean_standard_error / mean_luminance: what "1% error" means (0 for a black image).
    double relative_error = 0.0;
};
PathTraceError estimate_error(const PathTraceImage& image);

} // namespace sherpa::render
