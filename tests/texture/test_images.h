#pragma once
// Small deterministic test images: synthetic patterns and crops of the real corpus.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <sherpa/texture/image.h>
#include <sherpa/texture/texture_pipeline.h>

#include "test_support.h"

namespace sherpa::test {

// Pipeline options of the cache suites: the cache in `dir`, BC7 at its fastest level
// (these tests are about caching, not quality).
inline tex::PipelineOptions cache_test_options(const std::filesystem::path& dir) {
    tex::PipelineOptions o;
    o.cache_dir = dir;
    o.bc7_level = 0;
    return o;
}

// A w x h crop at (x, y) of a corpus image; fails the calling test via exception.
tex::RgbaImage load_crop(const std::filesystem::path& file, std::uint32_t x, std::uint32_t y,
                         std::uint32_t w, std::uint32_t h);

// Gradients, hard edges, noise and an alpha ramp: every BC7 mode has a use here.
tex::RgbaImage synthetic_image(std::uint32_t w, std::uint32_t h, bool with_alpha,
                               std::uint32_t seed);

// An image of one colour.
tex::RgbaImage constant_image(std::uint32_t w, std::uint32_t h, std::uint8_t r, std::uint8_t g,
                              std::uint8_t b, std::uint8_t a);

// PNG bytes of an image, as a glTF file would carry them (written and read back
// through a fresh temp directory named after `name`).
std::vector<std::uint8_t> png_bytes(const tex::RgbaImage& img, const std::string& name);

// A fresh empty directory under the system temp directory, named after the test.
std::filesystem::path fresh_temp_dir(const std::string& name);

} // namespace sherpa::test
