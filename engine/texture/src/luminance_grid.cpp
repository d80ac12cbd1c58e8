#include <sherpa/texture/luminance_grid.h>
#include <sherpa/texture/mips.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace sherpa::tex {

LuminanceGrid luminance_grid(std::uint32_t width, std::uint32_t height,
                             std::span<const std::uint8_t> rgba8_srgb) {
    LuminanceGrid g;
    if (width == 0 || height == 0 || rgba8_srgb.size() < std::size_t(width) * height * 4) return g;
    std::array<float, 256> linear;
    for (int i = 0; i < 256; ++i) linear[std::size_t(i)] = srgb_to_linear(float(i) / 255.0f);
    g.width = std::min(width, kLuminanceGridSize);
    g.height = std::min(height, kLuminanceGridSize);
    g.texels.assign(std::size_t(g.width) * g.height, 0.0f);
    // Each grid texel the mean of the source texels [x w / gw, (x + 1) w / gw).
    for (std::uint32_t gy = 0; gy < g.height; ++gy) {
        const std::uint32_t y0 = std::uint32_t(std::uint64_t(gy) * height / g.height);
        const std::uint32_t y1 = std::uint32_t(std::uint64_t(gy + 1) * height / g.height);
        for (std::uint32_t gx = 0; gx < g.width; ++gx) {
            const std::uint32_t x0 = std::uint32_t(std::uint64_t(gx) * width / g.width);
            const std::uint32_t x1 = std::uint32_t(std::uint64_t(gx + 1) * width / g.width);
            double sum = 0.0;
            for (std::uint32_t y = y0; y < y1; ++y)
                for (std::uint32_t x = x0; x < x1; ++x) {
                    const std::uint8_t* t = &rgba8_srgb[(std::size_t(y) * width + x) * 4];
                    sum += 0.2126 * linear[t[0]] + 0.7152 * linear[t[1]] + 0.0722 * linear[t[2]];
                }
            const double texel =
                sum / double(std::max<std::uint64_t>(1, std::uint64_t(y1 - y0) * (x1 - x0)));
            g.texels[std::size_t(gy) * g.width + gx] = float(texel);
            g.mean += texel;
        }
    }
    g.mean /= double(g.texels.size());
    return g;
}

namespace {
constexpr std::size_t kHeader = 2 * sizeof(std::uint32_t) + sizeof(double);
} // namespace

std::string encode_luminance_grid(const LuminanceGrid& g) {
    std::string out(kHeader + g.texels.size() * sizeof(float), '\0');
    std::memcpy(out.data(), &g.width, sizeof g.width);
    std::memcpy(out.data() + 4, &g.height, sizeof g.height);
    std::memcpy(out.data() + 8, &g.mean, sizeof g.mean);
    if (!g.texels.empty())
        std::memcpy(out.data() + kHeader, g.texels.data(), g.texels.size() * sizeof(float));
    return out;
}

bool decode_luminance_grid(const std::string& bytes, LuminanceGrid& g) {
    if (bytes.size() < kHeader) return false;
    LuminanceGrid out;
    std::memcpy(&out.width, bytes.data(), sizeof out.width);
    std::memcpy(&out.height, bytes.data() + 4, sizeof out.height);
    std::memcpy(&out.mean, bytes.data() + 8, sizeof out.mean);
    if (out.width == 0 || out.height == 0 || out.width > kLuminanceGridSize ||
        out.height > kLuminanceGridSize || !std::isfinite(out.mean) ||
        bytes.size() != kHeader + std::size_t(out.width) * out.height * sizeof(float))
        return false;
    out.texels.resize(std::size_t(out.width) * out.height);
    std::memcpy(out.texels.data(), bytes.data() + kHeader, out.texels.size() * sizeof(float));
    if (!std::all_of(out.texels.begin(), out.texels.end(),
                     [](float t) { return std::isfinite(t) && t >= 0.0f; }))
        return false;
    g = std::move(out);
    return true;
}

} // namespace sherpa::tex
