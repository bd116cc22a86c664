#include "marsokhod/nav/navigation.hpp"

#include <algorithm>
#include <cstdint>

namespace marsokhod::nav {
namespace {

constexpr int kRadius = 2; // 5 x 5

// Largest and smallest grey level over +-kRadius along a row (clamped at the edges). The
// interior is written as five whole-row passes, which the compiler turns into byte-vector
// maxima and minima.
void row_span(const std::uint8_t* row, int width, std::uint8_t* highest, std::uint8_t* lowest) {
  const auto clamped_span = [&](int x) {
    std::uint8_t hi = 0;
    std::uint8_t lo = 255;
    for (int dx = std::max(0, x - kRadius); dx <= std::min(width - 1, x + kRadius); ++dx) {
      hi = std::max(hi, row[dx]);
      lo = std::min(lo, row[dx]);
    }
    highest[x] = hi;
    lowest[x] = lo;
  };
  if (width <= 2 * kRadius) {
    for (int x = 0; x < width; ++x)
      clamped_span(x);
    return;
  }
  for (int x = kRadius; x < width - kRadius; ++x) {
    highest[x] = row[x - 2];
    lowest[x] = row[x - 2];
  }
  for (int offset = -1; offset <= kRadius; ++offset)
    for (int x = kRadius; x < width - kRadius; ++x) {
      highest[x] = std::max(highest[x], row[x + offset]);
      lowest[x] = std::min(lowest[x], row[x + offset]);
    }
  for (int x = 0; x < kRadius; ++x) {
    clamped_span(x);
    clamped_span(width - 1 - x);
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
  std::pmr::vector<std::uint8_t> hi(static_cast<std::size_t>(width), memory);
  std::pmr::vector<std::uint8_t> lo(static_cast<std::size_t>(width), memory);
  const auto threshold = static_cast<int>(grey_range);
  for (int y = 0; y < height; ++y) {
    std::copy_n(highest.row(y), width, hi.begin());
    std::copy_n(lowest.row(y), width, lo.begin());
    for (int dy = std::max(0, y - kRadius); dy <= std::min(height - 1, y + kRadius); ++dy) {
      const std::uint8_t* h = highest.row(dy);
      const std::uint8_t* l = lowest.row(dy);
      for (int x = 0; x < width; ++x) {
        hi[static_cast<std::size_t>(x)] = std::max(hi[static_cast<std::size_t>(x)], h[x]);
        lo[static_cast<std::size_t>(x)] = std::min(lo[static_cast<std::size_t>(x)], l[x]);
      }
    }
    std::uint8_t* out = textured.row(y);
    for (int x = 0; x < width; ++x)
      out[x] =
          hi[static_cast<std::size_t>(x)] - lo[static_cast<std::size_t>(x)] >= threshold ? 255 : 0;
  }
  return textured;
}

} // namespace marsokhod::nav
