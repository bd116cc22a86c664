// The charts' strokes.

#include "pictures/chart_drawing.hpp"

#include "pictures/bitmap_font.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace marsokhod::imaging::detail {

void dot(ImageView<std::uint8_t> rgb, int x, int y, Rgb colour) {
  if (!rgb.contains(x, y))
    return;
  for (int c = 0; c < 3; ++c)
    rgb(x, y, c) = colour[static_cast<std::size_t>(c)];
}

void square(ImageView<std::uint8_t> rgb, int x, int y, int half, Rgb colour) {
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx)
      dot(rgb, x + dx, y + dy, colour);
}

void line(ImageView<std::uint8_t> rgb, int x0, int y0, int x1, int y1, Rgb colour, int thick,
          int dash) {
  const int steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
  for (int i = 0; i <= steps; ++i) {
    if (dash > 0 && (i / dash) % 2 == 1)
      continue;
    const double t = steps == 0 ? 0.0 : static_cast<double>(i) / steps;
    const int x = x0 + static_cast<int>(std::lround(t * (x1 - x0)));
    const int y = y0 + static_cast<int>(std::lround(t * (y1 - y0)));
    square(rgb, x, y, thick / 2, colour);
  }
}

void box(ImageView<std::uint8_t> rgb, int x0, int y0, int x1, int y1, Rgb colour) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y)
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x)
      dot(rgb, x, y, colour);
}

void text(ImageView<std::uint8_t> rgb, int x, int y, const std::string& s, Rgb colour, int scale) {
  draw_text(rgb, x, y, s, scale, colour);
}

} // namespace marsokhod::imaging::detail
