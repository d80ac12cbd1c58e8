#pragma once
// What the lighting family measures with (lighting_images.cpp): which material each
// pixel shows, and how far one lit image is from another, over the whole image and per
// material. Pure functions over the scene and 8-bit images.
#include <cstdint>
#include <vector>

#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/scene.h>

namespace sherpa::lab::detail {

// Per pixel (top row first) the index into Scene::materials of the nearest triangle
// under the pixel's centre, -1 where no triangle is: primary rays from `camera`
// (perspective, its aspect) through a bounding volume hierarchy of the displayed
// scene's triangles in world space (bind pose; alpha not tested: a masked hole counts
// as its surface). Lines and points are left out.
std::vector<std::int32_t> material_id_image(const scene::Scene& scene,
                                            const scene::CameraSpec& camera, std::uint32_t width,
                                            std::uint32_t height);

// `rgba` (sRGB-encoded RGBA8, (width * factor) x (height * factor)) averaged over
// factor x factor boxes in linear values and encoded again: width x height.
std::vector<std::uint8_t> downsample_srgb(const std::vector<std::uint8_t>& rgba,
                                          std::uint32_t width, std::uint32_t height,
                                          std::uint32_t factor);

struct ImageDifference {
    double mean = 0.0;    // mean |a - b| over every pixel and RGB channel, 8-bit steps
    double psnr_db = 0.0; // 10 log10(255^2 / MSE); infinite where the images are equal
    std::uint64_t pixels = 0;
    // Per material (index into Scene::materials): mean |a - b| over its pixels, and
    // how many pixels it covers (0: not seen, mean 0).
    std::vector<double> material_mean;
    std::vector<std::uint64_t> material_pixels;
};

// a and b: RGBA8 of width x height (alpha ignored); `ids` from material_id_image(),
// `materials` the scene's material count (ids outside [0, materials) are background).
ImageDifference image_difference(const std::vector<std::uint8_t>& a,
                                 const std::vector<std::uint8_t>& b,
                                 const std::vector<std::int32_t>& ids, std::size_t materials);

} // namespace sherpa::lab::detail
