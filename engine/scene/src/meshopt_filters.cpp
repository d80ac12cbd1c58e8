// The meshopt filters (KHR_meshopt_compression, Appendix B), applied in place to decoded
// ATTRIBUTES data. The specification allows one unit in the last place on the octahedral,
// quaternion and color outputs and none on the exponential one: the tests hold this code
// to that against Debian's meshoptimizer and the npm meshoptimizer decoder.
#include "meshopt_codec.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sherpa::scene::meshopt {
namespace {

template <typename T> T load(const std::uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template <typename T> void store(std::uint8_t* p, T v) {
    std::memcpy(p, &v, sizeof v);
}

// round(v), halves away from zero, clamped to [lo, hi]; NaN gives 0. Garbage input
// (unspecified by the filters) never reaches an undefined float-to-int conversion.
int rounded(float v, int lo, int hi) {
    if (!(v > float(lo))) return v == v ? lo : 0; // below the range, or NaN
    if (!(v < float(hi))) return hi;
    return int(v + (v >= 0.0f ? 0.5f : -0.5f)); // truncation of v +- 0.5: halves away from 0
}

template <typename T> void octahedral(std::uint8_t* data, std::size_t count) {
    constexpr int kMax = (1 << (8 * sizeof(T) - 1)) - 1;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint8_t* e = data + i * 4 * sizeof(T);
        // The third input is the vector's 1.0 at its own bit count: working at that
        // scale and normalizing after is the specification's x / one, y / one.
        float x = float(load<T>(e)), y = float(load<T>(e + sizeof(T)));
        const float one = float(load<T>(e + 2 * sizeof(T)));
        const float z = one - std::fabs(x) - std::fabs(y);
        const float t = std::min(z, 0.0f); // fold the lower hemisphere back
        x -= std::copysign(t, x);
        y -= std::copysign(t, y);
        const float scale = float(kMax) / std::sqrt(x * x + y * y + z * z);
        store<T>(e, T(rounded(x * scale, -kMax, kMax)));
        store<T>(e + sizeof(T), T(rounded(y * scale, -kMax, kMax)));
        store<T>(e + 2 * sizeof(T), T(rounded(z * scale, -kMax, kMax)));
    }
}

void quaternion(std::uint8_t* data, std::size_t count) {
    const float range = 1.0f / std::sqrt(2.0f);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint8_t* e = data + i * 8;
        const auto packed = load<std::int16_t>(e + 6);
        const float scale = range / float(packed | 3); // the K-bit 1.0, low 2 bits: which
        const float x = float(load<std::int16_t>(e)) * scale;
        const float y = float(load<std::int16_t>(e + 2)) * scale;
        const float z = float(load<std::int16_t>(e + 4)) * scale;
        const float w = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y - z * z));
        const unsigned largest = unsigned(packed) & 3;
        const float values[4] = {w, x, y, z}; // the largest component, then the others
        std::int16_t out[4];
        for (unsigned c = 0; c < 4; ++c)
            out[(largest + c) % 4] = std::int16_t(rounded(values[c] * 32767.0f, -32767, 32767));
        std::memcpy(e, out, sizeof out);
    }
}

// 2^e * m, exact (as the specification demands) for the exponents it allows: a float
// of the value 2^e built from its bits, times m (at most 24 bits, so the product is
// exact wherever it is a normal float). Exponents below -126 (unspecified) go through
// ldexp.
void exponential(std::uint8_t* data, std::size_t values) {
    for (std::size_t i = 0; i < values; ++i) {
        const auto v = load<std::int32_t>(data + 4 * i);
        const int exponent = v >> 24;                                   // signed high 8 bits
        const auto mantissa = std::int32_t(std::uint32_t(v) << 8) >> 8; // signed low 24 bits
        float result;
        if (exponent >= -126) {
            float scale;
            const auto bits = std::uint32_t(exponent + 127) << 23;
            std::memcpy(&scale, &bits, 4);
            result = float(mantissa) * scale;
        } else {
            result = std::ldexp(float(mantissa), exponent);
        }
        store<float>(data + 4 * i, result);
    }
}

template <typename T> void color(std::uint8_t* data, std::size_t count) {
    using Signed = std::conditional_t<sizeof(T) == 1, std::int8_t, std::int16_t>;
    constexpr int kMax = (1 << (8 * sizeof(T))) - 1;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint8_t* e = data + i * 4 * sizeof(T);
        const int alpha_in = int(load<T>(e + 3 * sizeof(T)));
        // K from the alpha's top set bit; an alpha of 0 names no K (unspecified): K = 1.
        int msb = 0;
        while ((alpha_in >> (msb + 1)) != 0) ++msb;
        const int full = (1 << (msb + 1)) - 1;
        const int y = int(load<T>(e));
        const int co = int(load<Signed>(e + sizeof(T))), cg = int(load<Signed>(e + 2 * sizeof(T)));
        int a = alpha_in & (full >> 1);
        a = (a << 1) | (a & 1);
        const float scale = float(kMax) / float(full);
        const int rgba[4] = {y + co - cg, y + cg, y - co - cg, a};
        for (int c = 0; c < 4; ++c)
            store<T>(e + c * sizeof(T), T(rounded(float(rgba[c]) * scale, 0, kMax)));
    }
}

} // namespace

Result apply_filter(Filter filter, std::span<std::uint8_t> data, std::size_t count,
                    std::size_t stride) {
    const bool fits = stride != 0 && data.size() / stride >= count;
    switch (filter) {
    case Filter::None:
        return fits ? Result{} : Result{Status::BadArgument, 0};
    case Filter::Octahedral:
    case Filter::Color:
        if (!fits || (stride != 4 && stride != 8)) return {Status::BadArgument, 0};
        if (filter == Filter::Octahedral)
            stride == 4 ? octahedral<std::int8_t>(data.data(), count)
                        : octahedral<std::int16_t>(data.data(), count);
        else
            stride == 4 ? color<std::uint8_t>(data.data(), count)
                        : color<std::uint16_t>(data.data(), count);
        return {};
    case Filter::Quaternion:
        if (!fits || stride != 8) return {Status::BadArgument, 0};
        quaternion(data.data(), count);
        return {};
    case Filter::Exponential:
        if (!fits || stride % 4 != 0) return {Status::BadArgument, 0};
        exponential(data.data(), count * (stride / 4));
        return {};
    }
    return {Status::BadArgument, 0};
}

} // namespace sherpa::scene::meshopt
