#pragma once
// Error measures between an original RGBA8 image and its decoded compression.
#include <cstdint>
#include <span>

namespace sherpa::tex {

// Sum of squared differences over the channels selected by `channel_mask`
// (bit 0 = R ... bit 3 = A), with the number of samples it covers.
struct SquaredError {
    double sum = 0.0;
    std::uint64_t samples = 0;
    SquaredError& operator+=(const SquaredError& o) {
        sum += o.sum, samples += o.samples;
        return *this;
    }
    // Peak signal-to-noise ratio for 8-bit data; +infinity when identical.
    double psnr() const;
};

inline constexpr unsigned kChannelsRgb = 0b0111, kChannelsRgba = 0b1111, kChannelsRg = 0b0011;

// Both spans are RGBA8 of equal size (std::invalid_argument otherwise).
SquaredError squared_error(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b,
                           unsigned channel_mask);

// Normal maps stored as two channels: each texel's X and Y come from R and G
// (mapped to -1..1) and Z = sqrt(1 - x^2 - y^2). Sum of angles in degrees between
// the reconstructed normals of `a` and `b`, and the texel count.
struct AngleError {
    double sum_degrees = 0.0;
    std::uint64_t texels = 0;
    double mean() const { return texels ? sum_degrees / double(texels) : 0.0; }
};
AngleError normal_angle_error(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b);
// The same, but the reference is the source's own 3-channel normal, normalised
// (R, G, B of `source`), so the source's deviation from unit length and its
// quantised Z count as error too.
AngleError normal_angle_error_vs_rgb(std::span<const std::uint8_t> source,
                                     std::span<const std::uint8_t> two_channel);

} // namespace sherpa::tex
