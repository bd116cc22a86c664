// The navigation cycle's texture mask: pixels whose 5 x 5 neighbourhood is not featureless.

#include "marsokhod/nav/cycle/navigation.hpp"

#include <algorithm>
#include <cstdint>

namespace marsokhod::nav {
namespace {

constexpr int kRadius = 2; // 5 x 5

// Largest and smallest grey level over +-kRadius along a row (clamped at the edges). The
// interior is one pass of five-way maxima and minima, which the compiler turns into byte-vector
// instructions.
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
    highest[x] = std::max({row[x - 2], row[x - 1], row[x], row[x + 1], row[x + 2]});
    lowest[x] = std::min({row[x - 2], row[x - 1], row[x], row[x + 1], row[x + 2]});
  }
  for (int x = 0; x < kRadius; ++x) {
    clamped_span(x);
    clamped_span(width - 1 - x);
  }
}

// The spans of the last 2 * kRadius + 1 rows, row r in slot r % kRows: all that a row of the
// mask needs, without two whole images of spans.
class SpanRows {
public:
  static constexpr int kRows = 2 * kRadius + 1;

  SpanRows(int width, std::pmr::memory_resource* memory)
      : width_(width), highest_(static_cast<std::size_t>(kRows) * width, 0, memory),
        lowest_(static_cast<std::size_t>(kRows) * width, 0, memory) {}
  void compute(const std::uint8_t* row, int r) { row_span(row, width_, highest(r), lowest(r)); }
  std::uint8_t* highest(int r) { return highest_.data() + slot(r); }
  std::uint8_t* lowest(int r) { return lowest_.data() + slot(r); }

private:
  std::size_t slot(int r) const { return static_cast<std::size_t>(r % kRows) * width_; }
  int width_;
  std::pmr::vector<std::uint8_t> highest_;
  std::pmr::vector<std::uint8_t> lowest_;
};

// Row y of the mask: the spans of rows y - kRadius..y + kRadius (clamped; a repeated row changes
// no maximum or minimum) against the threshold, in one pass of byte lanes. The span never goes
// below zero, so it fits a byte.
void mark_textured(SpanRows& spans, int y, int height, int width, int grey_range,
                   std::uint8_t* out) {
  if (grey_range > 255)
    return;
  const auto threshold = static_cast<std::uint8_t>(std::max(grey_range, 0));
  const std::uint8_t* h[SpanRows::kRows];
  const std::uint8_t* l[SpanRows::kRows];
  for (int dy = -kRadius; dy <= kRadius; ++dy) {
    const int row = std::clamp(y + dy, 0, height - 1);
    h[dy + kRadius] = spans.highest(row);
    l[dy + kRadius] = spans.lowest(row);
  }
  for (int x = 0; x < width; ++x) {
    const std::uint8_t hi = std::max({h[0][x], h[1][x], h[2][x], h[3][x], h[4][x]});
    const std::uint8_t lo = std::min({l[0][x], l[1][x], l[2][x], l[3][x], l[4][x]});
    out[x] = static_cast<std::uint8_t>(hi - lo) >= threshold ? 255 : 0;
  }
}

} // namespace

imaging::Image<std::uint8_t> textured_pixels(imaging::ImageView<const std::uint8_t> image,
                                             int grey_range, std::pmr::memory_resource* memory) {
  const int width = image.width();
  const int height = image.height();
  imaging::Image<std::uint8_t> textured(width, height, 1, 0, memory);
  SpanRows spans(width, memory);
  int spanned = 0;
  for (int y = 0; y < height; ++y) {
    for (; spanned <= std::min(height - 1, y + kRadius); ++spanned)
      spans.compute(image.row(spanned), spanned);
    mark_textured(spans, y, height, width, grey_range, textured.row(y));
  }
  return textured;
}

} // namespace marsokhod::nav
