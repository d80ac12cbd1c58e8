// KHR_mesh_quantization's integer encodings (see quantize.h for the contracts).
#include <sherpa/lab/quantize.h>

#include <algorithm>
#include <cmath>

namespace sherpa::lab {
namespace {

template <int N> bool all_finite(const glm::vec<N, float>& v) {
    for (int a = 0; a < N; ++a)
        if (!std::isfinite(v[a])) return false;
    return true;
}

// Bounds of the finite elements; false when there is none.
template <int N>
bool finite_bounds(std::span<const glm::vec<N, float>> in, glm::vec<N, double>& lo,
                   glm::vec<N, double>& hi) {
    bool any = false;
    for (const auto& v : in) {
        if (!all_finite(v)) continue;
        const glm::vec<N, double> d(v);
        lo = any ? glm::min(lo, d) : d;
        hi = any ? glm::max(hi, d) : d;
        any = true;
    }
    return any;
}

double max_code(int bits) {
    return double((1u << bits) - 1u);
}

template <int N, typename Code>
std::size_t quantize(std::span<const glm::vec<N, float>> in, const glm::vec<N, double>& offset,
                     const glm::vec<N, double>& step, int bits, std::span<Code> codes) {
    std::size_t bad = 0;
    const double top = max_code(bits);
    for (std::size_t i = 0; i < in.size(); ++i) {
        Code c(0);
        if (all_finite(in[i])) {
            for (int a = 0; a < N; ++a)
                if (step[a] > 0.0)
                    c[a] = std::uint16_t(std::clamp(
                        std::nearbyint((double(in[i][a]) - offset[a]) / step[a]), 0.0, top));
        } else {
            ++bad;
        }
        codes[i] = c;
    }
    return bad;
}

template <int N, typename Code>
void dequantize(std::span<const Code> codes, const glm::vec<N, double>& offset,
                const glm::vec<N, double>& step, const glm::vec<N, double>& max,
                std::span<glm::vec<N, float>> out) {
    for (std::size_t i = 0; i < codes.size(); ++i)
        for (int a = 0; a < N; ++a)
            out[i][a] = float(std::min(offset[a] + double(codes[i][a]) * step[a], max[a]));
}

bool unorm_bits_ok(int bits) {
    return bits >= kMinUnormBits && bits <= kMaxQuantBits;
}

} // namespace

const char* to_string(GridStatus s) {
    switch (s) {
    case GridStatus::Ok:
        return "ok";
    case GridStatus::BitsOutOfRange:
        return "bits out of range";
    case GridStatus::NoFiniteValue:
        return "no finite value";
    }
    return "?";
}

GridStatus position_grid(std::span<const glm::vec3> positions, int bits, PositionGrid& out) {
    if (!unorm_bits_ok(bits)) return GridStatus::BitsOutOfRange;
    glm::dvec3 lo(0.0), hi(0.0);
    if (!finite_bounds<3>(positions, lo, hi)) return GridStatus::NoFiniteValue;
    const glm::dvec3 e = hi - lo;
    out = {lo, std::max({e.x, e.y, e.z}) / max_code(bits), hi, bits};
    return GridStatus::Ok;
}

GridStatus uv_grid(std::span<const glm::vec2> uvs, int bits, UvGrid& out) {
    if (!unorm_bits_ok(bits)) return GridStatus::BitsOutOfRange;
    glm::dvec2 lo(0.0), hi(0.0);
    if (!finite_bounds<2>(uvs, lo, hi)) return GridStatus::NoFiniteValue;
    out = {lo, (hi - lo) / max_code(bits), hi, bits};
    return GridStatus::Ok;
}

std::size_t quantize_positions(std::span<const glm::vec3> in, const PositionGrid& grid,
                               std::span<glm::u16vec3> codes) {
    return quantize<3>(in, grid.offset, glm::dvec3(grid.step), grid.bits, codes);
}

std::size_t quantize_uvs(std::span<const glm::vec2> in, const UvGrid& grid,
                         std::span<glm::u16vec2> codes) {
    return quantize<2>(in, grid.offset, grid.step, grid.bits, codes);
}

void dequantize_positions(std::span<const glm::u16vec3> codes, const PositionGrid& grid,
                          std::span<glm::vec3> out) {
    dequantize<3>(codes, grid.offset, glm::dvec3(grid.step), grid.max, out);
}

void dequantize_uvs(std::span<const glm::u16vec2> codes, const UvGrid& grid,
                    std::span<glm::vec2> out) {
    dequantize<2>(codes, grid.offset, grid.step, grid.max, out);
}

long quantize_snorm(std::span<const float> in, int bits, std::span<std::int16_t> codes) {
    if (bits < kMinSnormBits || bits > kMaxQuantBits) return -1;
    const float scale = float((1 << (bits - 1)) - 1);
    long bad = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (!std::isfinite(in[i])) {
            codes[i] = 0, ++bad;
            continue;
        }
        codes[i] = std::int16_t(std::nearbyint(std::clamp(in[i], -1.0f, 1.0f) * scale));
    }
    return bad;
}

void dequantize_snorm(std::span<const std::int16_t> codes, int bits, std::span<float> out) {
    const float scale = float((1 << (bits - 1)) - 1);
    for (std::size_t i = 0; i < codes.size(); ++i)
        out[i] = std::max(float(codes[i]) / scale, -1.0f);
}

std::uint32_t stream_stride(int components, int bits) {
    const std::uint32_t bytes = std::uint32_t(components) * (bits == 0 ? 4u : bits <= 8 ? 1u : 2u);
    return (bytes + 3u) & ~3u;
}

} // namespace sherpa::lab
