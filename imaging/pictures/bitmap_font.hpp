// Glyphs, text width and text drawing of the legend font (private to the pictures room).
#pragma once

// Internal: a tiny bitmap font for legends, so pictures need no font files at run time.

#include "marsokhod/imaging/image/image.hpp"

#include <array>
#include <cstdint>
#include <string_view>

namespace marsokhod::imaging::detail {

inline constexpr int kGlyphWidth = 5;
/// Seven rows from the cap line to the baseline, then two rows for descenders (g, j, p, q, y).
inline constexpr int kGlyphHeight = 9;
inline constexpr int kCapHeight = 7;
/// Horizontal distance between the starts of two characters, in font pixels.
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;

/// One character's rows, top first; '#' is ink, '.' is background.
using Glyph = std::array<std::string_view, kGlyphHeight>;

/// The glyph for c: digits, '.', '-', '+', a-z (A-Z drawn as a-z), space and a few signs;
/// anything else is drawn as '?'.
const Glyph& glyph_for(char c);

/// Whether the font has a glyph of its own for c (not the '?' stand-in).
bool has_glyph(char c);

/// Width in image pixels of text drawn at the given scale (each font pixel is scale x scale).
int text_width(std::string_view text, int scale);

/// Draws text with its top-left corner at (x, y) into an RGB image; ink outside is clipped.
void draw_text(ImageView<std::uint8_t> rgb, int x, int y, std::string_view text, int scale,
               std::array<std::uint8_t, 3> ink);

} // namespace marsokhod::imaging::detail
