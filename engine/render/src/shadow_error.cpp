#include <sherpa/render/debug_views.h>
#include <sherpa/render/shadow_error.h>

#include <array>
#include <cmath>

namespace sherpa::render {
namespace {

bool near(const std::uint8_t* px, const std::array<std::uint8_t, 3>& c) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(int(px[i]) - int(c[i])) > 1) return false;
    return true;
}

} // namespace

ShadowErrorCounts count_shadow_error(std::span<const std::uint8_t> rgba) {
    const auto lit = stored_bytes(kShadowAgreeLitColor),
               shadowed = stored_bytes(kShadowAgreeShadowedColor);
    const auto false_shadow = stored_bytes(kShadowFalseShadowColor);
    const auto false_light = stored_bytes(kShadowFalseLightColor);
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

} // namespace sherpa::render
