#include <sherpa/texture/bc5_normal.h>

namespace sherpa::tex {

void rebuild_bc5_z(std::span<std::uint8_t> rgba) {
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        const float x = rgba[i] / 127.5f - 1.0f, y = rgba[i + 1] / 127.5f - 1.0f;
        rgba[i + 2] = static_cast<std::uint8_t>(std::lround((bc5_normal_z(x, y) + 1.0f) * 127.5f));
    }
}

} // namespace sherpa::tex
