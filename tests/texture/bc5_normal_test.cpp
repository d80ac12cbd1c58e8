// BC5 normal maps keep x and y; sherpa::tex::bc5_normal_z / rebuild_bc5_z (the one
// C++ definition, used by the quality metrics and the editor's thumbnails) give z
// back from unit length. Checked against unit vectors built here.
#include <sherpa/texture/bc5_normal.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sherpa::tex {
namespace {

TEST(Bc5Normal, ZOfUnitVectors) {
    EXPECT_DOUBLE_EQ(bc5_normal_z(0.0, 0.0), 1.0);
    EXPECT_NEAR(bc5_normal_z(0.6, 0.0), 0.8, 1e-12);
    EXPECT_NEAR(bc5_normal_z(0.0f, -0.28f), 0.96f, 1e-6f);
    // Outside the unit disc (block compression can push a texel there): z is 0, not NaN.
    EXPECT_EQ(bc5_normal_z(0.9f, 0.9f), 0.0f);
}

TEST(Bc5Normal, RebuildWritesEncodedZIntoBlue) {
    // (x, y, z) unit vectors, encoded as v * 127.5 + 127.5 in R and G.
    const double normals[][3] = {{0.0, 0.0, 1.0}, {0.6, 0.0, 0.8}, {-0.48, 0.64, 0.6}};
    std::vector<std::uint8_t> rgba;
    for (const auto& n : normals)
        rgba.insert(rgba.end(),
                    {static_cast<std::uint8_t>(std::lround(n[0] * 127.5 + 127.5)),
                     static_cast<std::uint8_t>(std::lround(n[1] * 127.5 + 127.5)), 0, 255});
    rebuild_bc5_z(rgba);
    for (std::size_t i = 0; i < std::size(normals); ++i) {
        EXPECT_NEAR(rgba[i * 4 + 2], normals[i][2] * 127.5 + 127.5, 1.5) << i;
        EXPECT_EQ(rgba[i * 4 + 3], 255) << i;
    }
}

} // namespace
} // namespace sherpa::tex
