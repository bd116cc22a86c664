#include "marsokhod/nav/navigation.hpp"

#include <algorithm>
#include <cstdint>

namespace marsokhod::nav {
namespace {

constexpr int kRadius = 2; // 5 x 5

// Largest minus smallest grey level over +-kRadius along a row (clamped at the edges).
void row_span(const std::uint8_t* row, int width, std::uint8_t* highest, std::uint8_t* lowest) {
  for (int x = 0; x < width; ++x) {
    std::uint8_t hi = 0;
    std::uint8_t lo = 255;
    for (int dx = std::max(0, x - kRadius); dx <= std::min(width - 1, x + kRadius); ++dx) {
      hi = std::max(hi, row[dx]);
      lo = std::min(lo, row[dx]);
    }
    highest[x] = hi;
    lowest[x] = lo;
  }
}

} // namespace

Image<std::uint8_t> textured_pixels(ImageView<const std::uint8_t> image, int grey_range,
                                    std::pmr::memory_resource* memory) {
  const int width = image.width();
  const int height = image.height();
  Image<std::uint8_t> highest(width, height, 1, 0, memory);
  Image<std::uint8_t> lowest(width, height, 1, 0, memory);
  for (int y = 0; y < height; ++y)
    row_span(image.row(y), width, highest.row(y), lowest.row(y));
  Image<std::uint8_t> textured(width, height, 1, 0, memory);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int hi = 0;
      int lo = 255;
      for (int dy = std::max(0, y - kRadius); dy <= std::min(height - 1, y + kRadius); ++dy) {
        hi = std::max<int>(hi, highest(x, dy));
        lo = std::min<int>(lo, lowest(x, dy));
      }
      textured(x, y) = hi - lo >= grey_range ? 255 : 0;
    }
  return textured;
}

} // namespace marsokhod::nav
