// The validator's data pass: its typed kernels against plain per-value loops (every
// stride, count and non-finite value they can meet), and what it hands the importer
// (Validation::bounds_hold, which spares the importer a second scan of the same bytes).
#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "validate_internal.h" // engine/scene/src: DocumentValidator
#include "validate_kernels.h"

namespace {

namespace kernels = sherpa::scene::detail::kernels;

// `count` elements of N components of C, `stride` bytes apart, from `values` (flat).
template <typename C>
std::vector<std::uint8_t> strided(const std::vector<C>& values, std::uint32_t n,
                                  std::uint64_t stride) {
    const std::uint64_t count = values.size() / n;
    std::vector<std::uint8_t> bytes(count ? (count - 1) * stride + n * sizeof(C) : 0, 0xAB);
    for (std::uint64_t i = 0; i < count; ++i)
        std::memcpy(bytes.data() + i * stride, &values[i * n], n * sizeof(C));
    return bytes;
}

template <typename C, std::uint32_t N> void check_bounds(std::mt19937& rng, bool non_finite) {
    // Around the SIMD blocks' sizes (4 to 64 elements) and their remainders.
    for (std::uint64_t count : {0u, 1u, 15u, 16u, 17u, 31u, 32u, 33u, 64u, 65u, 100u, 1000u}) {
        for (std::uint64_t pad : {0u, 4u}) {
            std::vector<C> values(count * N);
            std::uniform_real_distribution<double> d(-1000, 1000);
            for (C& x : values) x = static_cast<C>(d(rng));
            if (non_finite && count) {
                const double special[] = {NAN, INFINITY, -INFINITY};
                values[rng() % values.size()] = static_cast<C>(special[rng() % 3]);
            }
            const std::uint64_t stride = N * sizeof(C) + pad;
            const auto bytes = strided(values, N, stride);
            C lo[N], hi[N];
            const bool finite = kernels::bounds<C, N>(bytes.data(), count, stride, lo, hi);
            bool want_finite = true;
            for (C x : values) want_finite &= std::isfinite(static_cast<double>(x));
            EXPECT_EQ(finite, want_finite) << "count " << count << " stride " << stride;
            if (!want_finite) continue; // the caller takes the exact path
            for (std::uint32_t c = 0; c < N && count; ++c) {
                C l = values[c], h = values[c];
                for (std::uint64_t i = 0; i < count; ++i) {
                    l = std::min(l, values[i * N + c]);
                    h = std::max(h, values[i * N + c]);
                }
                EXPECT_EQ(lo[c], l) << "component " << c << " count " << count;
                EXPECT_EQ(hi[c], h) << "component " << c << " count " << count;
            }
        }
    }
}

TEST(DataPassKernels, BoundsMatchAPlainLoop) {
    std::mt19937 rng(7);
    for (bool non_finite : {false, true}) {
        check_bounds<float, 1>(rng, non_finite);
        check_bounds<float, 2>(rng, non_finite);
        check_bounds<float, 3>(rng, non_finite);
        check_bounds<float, 4>(rng, non_finite);
        check_bounds<float, 16>(rng, non_finite);
    }
    check_bounds<std::int8_t, 3>(rng, false);
    check_bounds<std::uint16_t, 1>(rng, false);
    check_bounds<std::int16_t, 4>(rng, false);
    check_bounds<std::uint32_t, 1>(rng, false);
}

template <typename I> void check_indices(std::mt19937& rng) {
    const I restart = std::numeric_limits<I>::max();
    // Around the triangle blocks (3 vectors and the 2 values their last loads read
    // past them: 14, 26 or 50 values) and past 64 blocks, where lane counts are summed.
    for (std::uint64_t count :
         {0u, 1u, 2u, 3u, 4u, 9u, 10u, 14u, 15u, 26u, 27u, 50u, 51u, 52u, 300u, 3500u}) {
        for (std::uint64_t vertices : {0u, 1u, 5u, 200u}) {
            for (int variant = 0; variant < 3; ++variant) {
                std::vector<I> values(count);
                for (I& x : values)
                    x = static_cast<I>(vertices ? rng() % (vertices + 1) : rng() % 3);
                if (variant == 1 && count) values[rng() % count] = restart;
                if (variant == 2 && count) values[count / 2] = static_cast<I>(vertices);
                for (bool triangles : {false, true}) {
                    const auto bytes = strided(values, 1, sizeof(I));
                    const auto s =
                        kernels::indices<I>(bytes.data(), count, sizeof(I), vertices, triangles);
                    kernels::IndexScan want;
                    for (std::uint64_t i = 0; i < count; ++i) {
                        if (values[i] >= vertices && want.first_over == UINT64_MAX)
                            want.first_over = i;
                        if (values[i] == restart && want.first_restart == UINT64_MAX)
                            want.first_restart = i;
                        if (triangles && i % 3 == 2)
                            want.degenerate += values[i - 2] == values[i - 1] ||
                                               values[i - 1] == values[i] ||
                                               values[i] == values[i - 2];
                    }
                    // The summary's bounds, which the min/max check takes from it.
                    const auto sum =
                        kernels::summarize_indices<I>(bytes.data(), count, sizeof(I), triangles);
                    EXPECT_EQ(sum.degenerate, want.degenerate) << count << " " << vertices;
                    if (count) {
                        EXPECT_EQ(sum.low, *std::min_element(values.begin(), values.end()));
                        EXPECT_EQ(sum.high, *std::max_element(values.begin(), values.end()));
                    } else {
                        EXPECT_GT(sum.low, sum.high);
                    }
                    EXPECT_EQ(s.first_over, want.first_over) << count << " " << vertices;
                    EXPECT_EQ(s.first_restart, want.first_restart) << count << " " << vertices;
                    EXPECT_EQ(s.degenerate, want.degenerate) << count << " " << vertices;
                }
            }
        }
    }
}

TEST(DataPassKernels, IndicesMatchAPlainLoop) {
    std::mt19937 rng(11);
    check_indices<std::uint8_t>(rng);
    check_indices<std::uint16_t>(rng);
    check_indices<std::uint32_t>(rng);
}

// Unit vectors: lengths on both sides of the tolerance, by a hair, and non-finite ones
// (not reported: the Khronos validator skips them), with and without a sign.
TEST(DataPassKernels, UnitVectorsMatchAPlainLoop) {
    const double tol = 0.00674;
    const double lengths[] = {
        1.0, 1 + tol * 0.999, 1 + tol * 1.001, 1 - tol * 0.999, 1 - tol * 1.001, 0.5,
        NAN, INFINITY};
    for (double bad : lengths)
        for (float w : {1.0f, -1.0f, 0.5f})
            for (std::size_t at : {0u, 5u, 19u, 21u}) // 21: past the SIMD blocks
                for (int layout = 0; layout < 3; ++layout) {
                    // 3 floats packed (the SIMD path), 4 floats without and with a sign.
                    const bool sign = layout == 2;
                    const std::uint32_t n = layout == 0 ? 3 : 4;
                    std::vector<float> values;
                    for (std::size_t i = 0; i < 22; ++i) {
                        const double len = i == at ? bad : 1.0;
                        const float x = static_cast<float>(len * 0.6), y = 0,
                                    z = static_cast<float>(len * 0.8);
                        values.insert(values.end(), {x, y, z});
                        if (n == 4) values.push_back(i == at ? w : 1.0f);
                    }
                    const auto bytes = strided(values, n, n * sizeof(float));
                    const auto s =
                        kernels::unit_vectors(bytes.data(), 22, n * sizeof(float), tol, sign);
                    kernels::UnitScan want;
                    for (std::size_t i = 0; i < 22; ++i) {
                        const double x = values[i * n], y = values[i * n + 1],
                                     z = values[i * n + 2];
                        const double len = std::sqrt(x * x + y * y + z * z);
                        if (std::isfinite(len) && std::abs(len - 1) > tol &&
                            want.first_non_unit == UINT64_MAX)
                            want.first_non_unit = i;
                        const float wi = n == 4 ? values[i * n + 3] : 1.0f;
                        if (sign && wi != 1 && wi != -1 && want.first_bad_sign == UINT64_MAX)
                            want.first_bad_sign = i;
                    }
                    EXPECT_EQ(s.first_non_unit, want.first_non_unit) << bad << " at " << at;
                    EXPECT_EQ(s.first_bad_sign, want.first_bad_sign) << w << " at " << at;
                }
}

// Normals' bounds and first unit test in one pass: the same as bounds<float, 3> and
// the unit test apart, on every remainder of its blocks of 4 and with non-finite values.
TEST(DataPassKernels, UnitBoundsMatchBoundsAndUnitVectors) {
    const double tol = 0.00674;
    std::mt19937 rng(5);
    std::normal_distribution<float> d;
    for (std::uint64_t count : {0u, 1u, 3u, 4u, 5u, 8u, 11u, 64u, 67u}) {
        for (int variant = 0; variant < 4; ++variant) {
            std::vector<float> values;
            for (std::uint64_t i = 0; i < count; ++i) {
                float x = d(rng), y = d(rng), z = d(rng);
                const float len = std::sqrt(x * x + y * y + z * z);
                values.insert(values.end(), {x / len, y / len, z / len});
            }
            if (count && variant == 1) values[rng() % values.size()] *= 1.5f; // not unit
            if (count && variant == 2) values[rng() % values.size()] = NAN;
            if (count && variant == 3) values[values.size() - 1] = -INFINITY; // in the rest
            const auto bytes = strided(values, 3, 12);
            float lo[3], hi[3], want_lo[3], want_hi[3];
            bool doubtful = false;
            const bool finite = kernels::unit_bounds(bytes.data(), count, kernels::unit_band(tol),
                                                     lo, hi, doubtful);
            const bool want_finite =
                kernels::bounds<float, 3>(bytes.data(), count, 12, want_lo, want_hi);
            EXPECT_EQ(finite, want_finite) << count << " variant " << variant;
            const bool want_doubtful =
                kernels::unit_vectors(bytes.data(), count, 12, tol, false).first_non_unit !=
                    UINT64_MAX ||
                variant >= 2;
            if (count) {
                EXPECT_EQ(doubtful, want_doubtful) << count << " variant " << variant;
            }
            if (!want_finite) continue; // the caller takes the exact path
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(lo[c], want_lo[c]) << count;
                EXPECT_EQ(hi[c], want_hi[c]) << count;
            }
        }
    }
}

// The data pass tells the importer which accessors' values it found finite and inside
// their declared bounds; the importer skips its own scan of exactly those.
TEST(DataPass, BoundsHoldOnlyForValuesReadInFullAndInside) {
    // Accessor 0: inside; 1: a value above max; 2: a NaN; 3: sparse; 4: no min/max;
    // 5: declared min a float rounding away from the data (the Khronos comparison is
    // in single precision: still inside).
    const float data[] = {0, 1, 2, 3, 4, 5, NAN, 1, 0.1f, 0.2f};
    nlohmann::json root = nlohmann::json::parse(R"({
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": 40}],
        "bufferViews": [{"buffer": 0, "byteLength": 40}],
        "accessors": [
            {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 2,
             "type": "SCALAR", "min": [0], "max": [1]},
            {"bufferView": 0, "byteOffset": 8, "componentType": 5126, "count": 2,
             "type": "SCALAR", "min": [2], "max": [2.5]},
            {"bufferView": 0, "byteOffset": 24, "componentType": 5126, "count": 2,
             "type": "SCALAR", "min": [1], "max": [1]},
            {"bufferView": 0, "componentType": 5126, "count": 2, "type": "SCALAR",
             "min": [0], "max": [5], "sparse": {"count": 1,
               "indices": {"bufferView": 0, "componentType": 5125},
               "values": {"bufferView": 0, "byteOffset": 20}}},
            {"bufferView": 0, "componentType": 5126, "count": 2, "type": "SCALAR"},
            {"bufferView": 0, "byteOffset": 32, "componentType": 5126, "count": 2,
             "type": "SCALAR", "min": [0.1], "max": [0.2]}
        ]})");
    sherpa::scene::ValidationReport report;
    sherpa::scene::detail::DocumentValidator validator(root, {}, false, report);
    const std::span<const std::uint8_t> buffer(reinterpret_cast<const std::uint8_t*>(data),
                                               sizeof data);
    validator.check_data(std::span(&buffer, 1));
    const std::vector<std::uint8_t> hold = validator.take_bounds_hold();
    ASSERT_EQ(hold.size(), 6u);
    EXPECT_EQ(hold, (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 1}));
}

} // namespace

namespace {

bool has(const sherpa::scene::ValidationReport& r, std::string_view code, std::string_view pointer,
         std::string_view text) {
    for (const auto& m : r.messages)
        if (m.code == code && m.pointer == pointer && m.message.find(text) != std::string::npos)
            return true;
    return false;
}

// Triangle indices and normals long enough for the SIMD blocks, read once for both the
// min/max check and their use's checks: every message of both still fires, at the
// element the plain loops name.
TEST(DataPass, SummarizedAccessorsKeepEveryMessage) {
    constexpr std::size_t kVertices = 100, kIndices = 300;
    std::vector<std::uint8_t> bytes(kVertices * 24 + kIndices * 2);
    std::vector<float> positions, normals;
    for (std::size_t i = 0; i < kVertices; ++i) {
        positions.insert(positions.end(), {float(i % 10), float(i / 10), 0});
        normals.insert(normals.end(), {0, 0, i == 77 ? 1.5f : 1.0f}); // 77: not unit
    }
    std::vector<std::uint16_t> indices;
    for (std::size_t i = 0; i < kIndices; ++i) indices.push_back(std::uint16_t(i % kVertices));
    indices[250] = 140;        // past the 100 vertices
    indices[31] = indices[30]; // triangle 10 repeats an index
    std::memcpy(bytes.data(), positions.data(), kVertices * 12);
    std::memcpy(bytes.data() + kVertices * 12, normals.data(), kVertices * 12);
    std::memcpy(bytes.data() + kVertices * 24, indices.data(), kIndices * 2);
    nlohmann::json root = nlohmann::json::parse(R"({
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": 3000}],
        "bufferViews": [{"buffer": 0, "byteLength": 2400, "byteStride": 12, "target": 34962},
                        {"buffer": 0, "byteOffset": 2400, "byteLength": 600, "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 100, "type": "VEC3",
             "min": [0, 0, 0], "max": [9, 9, 0]},
            {"bufferView": 0, "byteOffset": 1200, "componentType": 5126, "count": 100,
             "type": "VEC3", "min": [0, 0, 1], "max": [0, 0, 1]},
            {"bufferView": 1, "componentType": 5123, "count": 300, "type": "SCALAR",
             "min": [0], "max": [99]}
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1},
                                    "indices": 2}]}]})");
    sherpa::scene::ValidationReport report;
    sherpa::scene::detail::DocumentValidator validator(root, {}, false, report);
    const std::span<const std::uint8_t> buffer(bytes);
    validator.check_data(std::span(&buffer, 1));
    EXPECT_TRUE(has(report, "ACCESSOR_MAX_MISMATCH", "/accessors/1/max/2", "(1.500000)"));
    EXPECT_TRUE(
        has(report, "ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND", "/accessors/1/max/2", "1 element(s)"));
    EXPECT_TRUE(has(report, "ACCESSOR_VECTOR3_NON_UNIT", "/meshes/0/primitives/0/attributes/NORMAL",
                    "element 77 "));
    EXPECT_TRUE(has(report, "ACCESSOR_MAX_MISMATCH", "/accessors/2/max/0", "(140.000000)"));
    EXPECT_TRUE(has(report, "ACCESSOR_INDEX_OOB", "/meshes/0/primitives/0/indices",
                    "index 250 has value 140"));
    EXPECT_TRUE(has(report, "ACCESSOR_INDEX_TRIANGLE_DEGENERATE", "/meshes/0/primitives/0/indices",
                    "contains 1 degenerate"));
    const std::vector<std::uint8_t> hold = validator.take_bounds_hold();
    EXPECT_EQ(hold, (std::vector<std::uint8_t>{1, 0, 0}));
}

} // namespace
