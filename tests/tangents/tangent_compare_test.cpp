// Angle statistics between tangent sets (what --compare and the reports print).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <sherpa/scene/tangent_compare.h>

namespace sherpa {
namespace {

TEST(TangentCompare, AnglesAreExactEvenWhenTiny) {
    EXPECT_NEAR(scene::tangent_angle_degrees({1, 0, 0, 1}, {0, 1, 0, 1}), 90.0, 1e-12);
    EXPECT_NEAR(scene::tangent_angle_degrees({1, 0, 0, 1}, {-1, 0, 0, 1}), 180.0, 1e-12);
    const float tiny = 1e-6f; // radians
    EXPECT_NEAR(scene::tangent_angle_degrees({1, 0, 0, 1}, {1, tiny, 0, 1}),
                1e-6 * 180.0 / 3.14159265358979, 1e-12);
    // Lengths do not matter.
    EXPECT_NEAR(scene::tangent_angle_degrees({2, 0, 0, 1}, {0, 0, 5, 1}), 90.0, 1e-12);
}

TEST(TangentCompare, StatisticsFlipsSkipsAndNonFinite) {
    std::vector<glm::vec4> a, b;
    for (int i = 0; i < 100; ++i) {
        a.push_back({1, 0, 0, 1});
        const double angle = glm::radians(i < 99 ? 1.0 : 10.0);
        b.push_back({float(std::cos(angle)), float(std::sin(angle)), 0, i < 3 ? -1.0f : 1.0f});
    }
    a.push_back({std::numeric_limits<float>::quiet_NaN(), 0, 0, 1});
    b.push_back({1, 0, 0, 1});
    scene::TangentComparison c = scene::compare_tangents(a, b);
    EXPECT_EQ(c.corners, 100u);
    EXPECT_EQ(c.nonfinite, 1u);
    EXPECT_EQ(c.flips, 3u);
    EXPECT_NEAR(c.max, 10.0, 1e-4);
    EXPECT_NEAR(c.p99, 1.0, 1e-4);
    EXPECT_NEAR(c.mean, (99 * 1.0 + 10.0) / 100.0, 1e-4);
    std::vector<std::uint8_t> skip(a.size(), 0);
    skip[99] = 1;
    c = scene::compare_tangents(a, b, skip);
    EXPECT_EQ(c.corners, 99u);
    EXPECT_NEAR(c.max, 1.0, 1e-4);
    EXPECT_EQ(scene::compare_tangents({}, {}).corners, 0u);
    EXPECT_THROW(scene::compare_tangents(a, std::vector<glm::vec4>(3)), std::invalid_argument);
}

} // namespace
} // namespace sherpa
