#pragma once
// The material sweeps (tests/data/material_sweeps, tools/material_sweeps/make_sweeps.py)
// as the CLI tests read them: the file of a sweep, the camera that frames its two rows
// of five spheres, and the rendered PNG with the pixel at a sphere's centre.
#include "test_support.h"

#include <sherpa/texture/image.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

namespace sherpa::test {

inline std::string sweep(const std::string& name) {
    return (data_dir() / "material_sweeps" / (name + ".gltf")).string();
}

inline constexpr const char* kSweepCamera = " --camera eye=0,0,5:target=0,0,0:fov=45";

struct Png {
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint8_t> rgba;
    const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const {
        return &rgba[(y * w + x) * 4];
    }
};

inline Png read_png(const std::string& path) {
    Png p;
    std::string error;
    EXPECT_TRUE(tex::read_png_rgba8(path, p.w, p.h, p.rgba, error)) << error;
    return p;
}

// The pixel at the centre of sphere (row, column) of a sweep seen by kSweepCamera.
inline const std::uint8_t* sphere_centre(const Png& p, int row, int column) {
    const double half = 5.0 * std::tan(22.5 * 3.14159265358979 / 180.0);
    const double x = (column - 2.0) / (half * p.w / p.h), y = (0.5 - row) / half;
    return p.at(std::uint32_t(p.w * 0.5 * (1.0 + x)), std::uint32_t(p.h * 0.5 * (1.0 - y)));
}

} // namespace sherpa::test
