#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/ktx2.h>
#include <sherpa/texture/prepared_levels.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sherpa::tex {

void rebuild_normal_z(std::span<std::uint8_t> rgba) {
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        const float x = rgba[i] / 127.5f - 1.0f, y = rgba[i + 1] / 127.5f - 1.0f;
        const float z = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y));
        rgba[i + 2] = static_cast<std::uint8_t>(std::lround((z + 1.0f) * 127.5f));
    }
}

std::vector<std::uint8_t> decode_level_rgba8(const PreparedTexture& texture, std::uint32_t level) {
    if (texture.failed || level >= texture.levels.size()) return {};
    const std::uint32_t w = mip_extent(texture.width, level), h = mip_extent(texture.height, level);
    std::vector<std::uint8_t> rgba;
    try {
        if (texture.format == VkFormat::Bc7SrgbBlock || texture.format == VkFormat::Bc7UnormBlock) {
            rgba = decode_image(BlockFormat::Bc7, texture.levels[level], w, h, 1);
        } else if (texture.format == VkFormat::Bc5UnormBlock) {
            rgba = decode_image(BlockFormat::Bc5, texture.levels[level], w, h, 1);
            rebuild_normal_z(rgba);
        } else {
            rgba = texture.levels[level];
        }
    } catch (const std::invalid_argument&) {
        return {}; // blocks of the wrong size for the level
    }
    if (rgba.size() != std::size_t(w) * h * 4) return {};
    return rgba;
}

} // namespace sherpa::tex
