#include <sherpa/texture/bc5_normal.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/ktx2.h>
#include <sherpa/texture/prepared_levels.h>

#include <stdexcept>

namespace sherpa::tex {

std::vector<std::uint8_t> decode_level_rgba8(const PreparedTexture& texture, std::uint32_t level) {
    if (texture.failed || level >= texture.levels.size()) return {};
    const std::uint32_t w = mip_extent(texture.width, level), h = mip_extent(texture.height, level);
    std::vector<std::uint8_t> rgba;
    try {
        if (texture.format == VkFormat::Bc7SrgbBlock || texture.format == VkFormat::Bc7UnormBlock) {
            rgba = decode_image(BlockFormat::Bc7, texture.levels[level], w, h, 1);
        } else if (texture.format == VkFormat::Bc5UnormBlock) {
            rgba = decode_image(BlockFormat::Bc5, texture.levels[level], w, h, 1);
            rebuild_bc5_z(rgba); // z from x and y, as shaded
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
