// The strokes the charts are drawn with: dots, squares, lines and text in RGB.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <array>
#include <cstdint>
#include <string>

namespace marsokhod::imaging::detail {

using Rgb = std::array<std::uint8_t, 3>;
inline constexpr Rgb kInk{30, 30, 30};
inline constexpr Rgb kGrid{225, 225, 225};
inline constexpr Rgb kCurve{31, 119, 180};
inline constexpr Rgb kMissing{214, 39, 40};
inline constexpr Rgb kMark{120, 120, 120};
inline constexpr int kTitleScale = 2; // the title's font pixels are 2 x 2, the rest 1 x 1

/// One pixel; nothing outside the picture.
void dot(ImageView<std::uint8_t> rgb, int x, int y, Rgb colour);
/// A square of 2 `half` + 1 pixels centred on (x, y).
void square(ImageView<std::uint8_t> rgb, int x, int y, int half, Rgb colour);
/// A line `thick` pixels wide; every `dash` pixels on, then as many off (0: solid).
void line(ImageView<std::uint8_t> rgb, int x0, int y0, int x1, int y1, Rgb colour, int thick,
          int dash = 0);
/// A filled rectangle [x0, x1] x [y0, y1].
void box(ImageView<std::uint8_t> rgb, int x0, int y0, int x1, int y1, Rgb colour);
void text(ImageView<std::uint8_t> rgb, int x, int y, const std::string& s, Rgb colour,
          int scale = 1);

} // namespace marsokhod::imaging::detail
