#pragma once
// What the three.js render oracle tests read of a PNG: its pixels, and the mean colour
// of a disk (inside a sphere of a test scene).
#include <sherpa/texture/image.h>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sherpa::test {

struct Image {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

inline Image read(const std::filesystem::path& p) {
    Image img;
    std::string error;
    EXPECT_TRUE(tex::read_png_rgba8(p.string(), img.width, img.height, img.rgba, error)) << error;
    return img;
}

// Mean 8-bit colour (/255) of the pixels whose centres lie within `r` of (cx, cy).
inline glm::dvec3 disk_mean(const Image& img, double cx, double cy, double r) {
    glm::dvec3 sum(0.0);
    int n = 0;
    for (int py = int(cy - r); py <= int(cy + r); ++py)
        for (int px = int(cx - r); px <= int(cx + r); ++px) {
            if ((px + 0.5 - cx) * (px + 0.5 - cx) + (py + 0.5 - cy) * (py + 0.5 - cy) > r * r)
                continue;
            const std::uint8_t* p = &img.rgba[(std::size_t(py) * img.width + std::size_t(px)) * 4];
            sum += glm::dvec3(p[0], p[1], p[2]) / 255.0;
            ++n;
        }
    return sum / double(std::max(n, 1));
}

} // namespace sherpa::test
