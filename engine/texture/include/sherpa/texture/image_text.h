#pragma once
// Labels drawn into RGBA8 images (the legends of the CLI's images: `compare --image`,
// render's provenance view) with a built-in 5x7 bitmap font, so that the numbers a
// legend stands for are in the picture, not only on stdout. Printable ASCII; any
// other byte draws as '?'. Everything is clipped to the image.
#include <sherpa/texture/image.h>

#include <array>
#include <cstdint>
#include <string_view>

namespace sherpa::tex {

using Rgb8 = std::array<std::uint8_t, 3>;

inline constexpr std::uint32_t kGlyphWidth = 5, kGlyphHeight = 7;
inline constexpr std::uint32_t kGlyphAdvance = kGlyphWidth + 1; // one column between glyphs

// Rows of the glyph for `c`, top first; bit 4 is the leftmost column.
std::array<std::uint8_t, kGlyphHeight> glyph_rows(char c);

// Width in pixels of `text` at `scale` (each font pixel a scale x scale block),
// without the trailing gap.
std::uint32_t text_width(std::string_view text, std::uint32_t scale = 1);

// Draws `text` with its top-left corner at (x, y): only the glyphs' set pixels.
void draw_text(RgbaImage& image, int x, int y, std::string_view text, Rgb8 colour,
               std::uint32_t scale = 1);

// Fills the rectangle [x, x + w) x [y, y + h) with an opaque colour.
void fill_rect(RgbaImage& image, int x, int y, int w, int h, Rgb8 colour);

} // namespace sherpa::tex
