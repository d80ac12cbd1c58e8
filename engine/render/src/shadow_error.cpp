#include <sherpa/gpu/debug_views.h>
#include <sherpa/render/shadow_error.h>

#include <array>
#include <cmath>

namespace sherpa::gpu {
namespace {

// The stored bytes of a class colour (data views store values, not sRGB).
std::array<std::uint8_t, 3> bytes(const std::array<float, 3>& c) {
    std::array<std::uint8_t, 3> b{};
    for (int i = 0; i < 3; ++i) b[i] = static_cast<std::uint8_t>(std::lround(c[i] * 255.0f));
    return b;
}

bool near(const std::uint8_t* px, const std::array<std::uint8_t, 3>& c) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(int(px[i]) - int(c[i])) > 1) return false;
    return true;
}

} // namespace

ShadowErrorCounts count_shadow_error(std::span<const std::uint8_t> rgba) {
    const auto lit = bytes(kShadowAgreeLitColor), shadowed = bytes(kShadowAgreeShadowedColor);
    const auto false_shadow = bytes(kShadowFalseShadowColor);
    const auto false_light = bytes(kShadowFalseLightColor);
    ShadowErrorCounts n;
    for (std::size_t p = 0; p + 4 <= rgba.size(); p += 4) {
        const std::uint8_t* px = rgba.data() + p;
        if (near(px, lit))
            ++n.agree_lit;
        else if (near(px, shadowed))
            ++n.agree_shadowed;
        else if (near(px, false_shadow))
            ++n.false_shadow;
        else if (near(px, false_light))
            ++n.false_light;
        else
            ++n.other;
    }
    return n;
}

} // namespace sherpa::gpu
