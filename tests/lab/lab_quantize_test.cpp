// KHR_mesh_quantization's encodings (sherpa/lab/quantize.h): the half-step bound, the
// bit-count limits, and degenerate and hostile input (zero extent, one vertex, NaN and
// infinity, coordinates near the float range).
#include <sherpa/lab/quantize.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace {

using namespace sherpa::lab;

// Half a float ulp of x: the rounding of the decoded value to float.
double half_ulp(double x) {
    const float f = float(std::abs(x));
    return 0.5 * double(std::nextafter(f, INFINITY) - f);
}

std::vector<glm::vec3> random_positions(std::size_t n, float lo, float hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> d(lo, hi);
    std::vector<glm::vec3> p(n);
    for (auto& v : p) v = {d(rng), d(rng) * 0.5f, d(rng) * 0.25f};
    return p;
}

// Quantizes and decodes; returns the largest per-axis error minus its bound (<= 0 ok).
double worst_excess(const std::vector<glm::vec3>& p, int bits, double* max_error = nullptr) {
    PositionGrid g;
    EXPECT_EQ(position_grid(p, bits, g), GridStatus::Ok);
    std::vector<glm::u16vec3> codes(p.size());
    std::vector<glm::vec3> out(p.size());
    EXPECT_EQ(quantize_positions(p, g, codes), 0u);
    dequantize_positions(codes, g, out);
    double excess = -INFINITY, worst = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(double(codes[i][a]), double((1u << bits) - 1u));
            const double e = std::abs(double(out[i][a]) - double(p[i][a]));
            worst = std::max(worst, e);
            excess = std::max(excess, e - (g.step / 2 + half_ulp(out[i][a])));
        }
    if (max_error) *max_error = worst;
    return excess;
}

TEST(LabQuantize, PositionsWithinHalfAStepPerAxisForEveryBitCount) {
    const auto p = random_positions(2000, -3.0f, 5.0f, 7);
    double previous = INFINITY;
    for (int bits = kMinUnormBits; bits <= kMaxQuantBits; ++bits) {
        double max_error = 0.0;
        EXPECT_LE(worst_excess(p, bits, &max_error), 0.0) << bits << " bits";
        EXPECT_LE(max_error, previous) << "error falls with bits: " << bits;
        previous = max_error;
    }
    PositionGrid g;
    ASSERT_EQ(position_grid(p, 16, g), GridStatus::Ok);
    std::vector<glm::u16vec3> codes(p.size());
    quantize_positions(p, g, codes);
    std::uint16_t top = 0;
    for (auto c : codes) top = std::max(top, c.x);
    EXPECT_EQ(top, 65535) << "the largest axis spans the whole code range";
}

TEST(LabQuantize, BitCountsOutsideTheLimitsAreRefused) {
    const std::vector<glm::vec3> p{{0, 0, 0}, {1, 1, 1}};
    const std::vector<glm::vec2> uv{{0, 0}, {1, 1}};
    PositionGrid g;
    UvGrid u;
    for (int bits : {-1, 0, 17, 32}) {
        EXPECT_EQ(position_grid(p, bits, g), GridStatus::BitsOutOfRange) << bits;
        EXPECT_EQ(uv_grid(uv, bits, u), GridStatus::BitsOutOfRange) << bits;
    }
    EXPECT_EQ(position_grid(p, 1, g), GridStatus::Ok);
    EXPECT_EQ(g.step, 1.0) << "1 bit: codes 0 and 1 at the two ends";
    const std::vector<float> v{0.5f};
    std::vector<std::int16_t> c(1, 99);
    EXPECT_EQ(quantize_snorm(v, 1, c), -1) << "snorm needs a sign bit and one more";
    EXPECT_EQ(quantize_snorm(v, 17, c), -1);
    EXPECT_EQ(c[0], 99) << "nothing written";
}

TEST(LabQuantize, ZeroExtentAndOneVertexDecodeExactly) {
    for (const std::vector<glm::vec3>& p :
         {std::vector<glm::vec3>{{1.5f, -2.0f, 3.25f}},
          std::vector<glm::vec3>(5, glm::vec3(1e30f, -7.0f, 0.1f))}) {
        PositionGrid g;
        ASSERT_EQ(position_grid(p, 8, g), GridStatus::Ok);
        EXPECT_EQ(g.step, 0.0);
        std::vector<glm::u16vec3> codes(p.size());
        std::vector<glm::vec3> out(p.size());
        quantize_positions(p, g, codes);
        dequantize_positions(codes, g, out);
        for (std::size_t i = 0; i < p.size(); ++i) {
            EXPECT_EQ(codes[i], glm::u16vec3(0));
            EXPECT_EQ(out[i], p[i]);
        }
    }
    PositionGrid g;
    EXPECT_EQ(position_grid({}, 8, g), GridStatus::NoFiniteValue);
}

TEST(LabQuantize, NonFiniteValuesAreCountedAndLeaveTheGridAlone) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = INFINITY;
    const std::vector<glm::vec3> p{{0, 0, 0}, {nan, 0, 0}, {1, 2, 4}, {0, inf, 0}};
    PositionGrid g;
    ASSERT_EQ(position_grid(p, 10, g), GridStatus::Ok);
    EXPECT_EQ(g.offset, glm::dvec3(0.0));
    EXPECT_DOUBLE_EQ(g.step, 4.0 / 1023.0);
    std::vector<glm::u16vec3> codes(p.size());
    std::vector<glm::vec3> out(p.size());
    EXPECT_EQ(quantize_positions(p, g, codes), 2u);
    dequantize_positions(codes, g, out);
    EXPECT_EQ(codes[1], glm::u16vec3(0));
    EXPECT_EQ(out[3], glm::vec3(0.0f)) << "coded as the grid's minimum";
    EXPECT_NEAR(out[2].z, 4.0f, 1e-6f);
    const std::vector<glm::vec3> all_bad{{nan, nan, nan}, {inf, 0, 0}};
    EXPECT_EQ(position_grid(all_bad, 10, g), GridStatus::NoFiniteValue);
    const std::vector<float> n{nan, -inf, 0.5f, 2.0f, -1.0f};
    std::vector<std::int16_t> c(n.size());
    EXPECT_EQ(quantize_snorm(n, 8, c), 2);
    EXPECT_EQ(c[0], 0);
    EXPECT_EQ(c[1], 0);
    EXPECT_EQ(c[3], 127) << "clamped to 1";
    EXPECT_EQ(c[4], -127);
}

TEST(LabQuantize, CoordinatesNearTheFloatRange) {
    const float big = 3.0e38f;
    const std::vector<glm::vec3> p{
        {-big, -big, 0}, {big, big, 1}, {0, 0, 0}, {1e37f, -2e38f, 5}, {big, -big, -big}};
    for (int bits : {1, 8, 16}) {
        EXPECT_LE(worst_excess(p, bits), 0.0) << bits;
        PositionGrid g;
        ASSERT_EQ(position_grid(p, bits, g), GridStatus::Ok);
        EXPECT_TRUE(std::isfinite(g.step));
        std::vector<glm::u16vec3> codes(p.size());
        std::vector<glm::vec3> out(p.size());
        quantize_positions(p, g, codes);
        dequantize_positions(codes, g, out);
        for (const glm::vec3& v : out)
            EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    }
    // A small mesh far from the origin: the step is small, the float ulp is not.
    const auto far = random_positions(200, 1.0e7f, 1.0e7f + 1.0f, 3);
    EXPECT_LE(worst_excess(far, 16), 0.0);
}

TEST(LabQuantize, UvsWithinHalfAStepPerAxis) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> d(-0.5f, 3.0f);
    std::vector<glm::vec2> uv(1000);
    for (auto& v : uv) v = {d(rng), d(rng) * 0.1f};
    double previous = INFINITY;
    for (int bits = kMinUnormBits; bits <= kMaxQuantBits; ++bits) {
        UvGrid g;
        ASSERT_EQ(uv_grid(uv, bits, g), GridStatus::Ok);
        EXPECT_GT(g.step.x, g.step.y) << "one step per axis";
        std::vector<glm::u16vec2> codes(uv.size());
        std::vector<glm::vec2> out(uv.size());
        quantize_uvs(uv, g, codes);
        dequantize_uvs(codes, g, out);
        double worst = 0.0;
        for (std::size_t i = 0; i < uv.size(); ++i)
            for (int a = 0; a < 2; ++a) {
                const double e = std::abs(double(out[i][a]) - double(uv[i][a]));
                EXPECT_LE(e, g.step[a] / 2 + half_ulp(out[i][a])) << bits;
                worst = std::max(worst, e);
            }
        EXPECT_LE(worst, previous);
        previous = worst;
    }
}

TEST(LabQuantize, SnormKeepsTheEndsAndHalfAStep) {
    for (int bits = kMinSnormBits; bits <= kMaxQuantBits; ++bits) {
        const float scale = float((1 << (bits - 1)) - 1);
        std::vector<float> v;
        for (int i = -1000; i <= 1000; ++i) v.push_back(float(i) / 1000.0f);
        std::vector<std::int16_t> c(v.size());
        std::vector<float> out(v.size());
        ASSERT_EQ(quantize_snorm(v, bits, c), 0);
        dequantize_snorm(c, bits, out);
        EXPECT_EQ(out.front(), -1.0f);
        EXPECT_EQ(out.back(), 1.0f);
        EXPECT_EQ(out[1000], 0.0f);
        for (std::size_t i = 0; i < v.size(); ++i)
            EXPECT_LE(std::abs(out[i] - v[i]), 0.5f / scale + 1e-6f) << bits;
    }
    const std::vector<std::int16_t> below{-128};
    std::vector<float> out(1);
    dequantize_snorm(below, 8, out);
    EXPECT_EQ(out[0], -1.0f) << "glTF clamps -128/127 to -1";
}

TEST(LabQuantize, StreamStridesFollowTheFourByteAlignment) {
    EXPECT_EQ(stream_stride(3, 0), 12u);
    EXPECT_EQ(stream_stride(3, 1), 4u);
    EXPECT_EQ(stream_stride(3, 8), 4u);
    EXPECT_EQ(stream_stride(3, 9), 8u);
    EXPECT_EQ(stream_stride(3, 16), 8u);
    EXPECT_EQ(stream_stride(4, 0), 16u);
    EXPECT_EQ(stream_stride(4, 8), 4u);
    EXPECT_EQ(stream_stride(4, 12), 8u);
    EXPECT_EQ(stream_stride(2, 0), 8u);
    EXPECT_EQ(stream_stride(2, 8), 4u);
    EXPECT_EQ(stream_stride(2, 16), 4u);
}

} // namespace
