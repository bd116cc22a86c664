// The coarser layer's disparities turned into the finer layer's search windows (private).

#include "stereo/coarse_guide.hpp"

#include "lanes/simd_lanes.hpp"
#include "matching/band_layout.hpp"

#include <algorithm>

namespace marsokhod::nav::detail {
namespace {

// Disparities are never negative: truncation is the floor.
int floor_of(float disparity) {
  return static_cast<std::int32_t>(disparity);
}
int ceiling_of(float disparity) {
  const auto whole = static_cast<std::int32_t>(disparity);
  return whole + (static_cast<float>(whole) < disparity ? 1 : 0);
}

} // namespace

CoarseGuide::CoarseGuide(imaging::ImageView<const float> coarse, std::pmr::memory_resource* memory)
    : coarse_(coarse), column_low_(static_cast<std::size_t>(coarse.width()), 0.0F, memory),
      column_high_(static_cast<std::size_t>(coarse.width()), 0.0F, memory) {}

// The extremes over the 3x3 neighbourhoods of a block of coarse pixels are the extremes over
// the block grown by one pixel (within the image), and the floor of the smallest (the ceiling
// of the largest) is the smallest floor (the largest ceiling): both are monotonic. So each band
// takes column extremes over its grown rows once, then each tile over its grown columns.
void CoarseGuide::wanted(int y0, int width, int band, std::span<int> low, std::span<int> high) {
  const int columns = coarse_.width();
  const int last_column = columns - 1;
  const int last_row = coarse_.height() - 1;
  const int top = std::max(std::min(y0 / 2, last_row) - 1, 0);
  const int bottom = std::min(std::min((y0 + kBandRows - 1) / 2, last_row) + 1, last_row);
  float* lows = column_low_.data();
  float* highs = column_high_.data();
  std::copy(coarse_.row(top), coarse_.row(top) + columns, lows);
  std::copy(coarse_.row(top), coarse_.row(top) + columns, highs);
  for (int y = top + 1; y <= bottom; ++y) {
    const float* row = coarse_.row(y);
    int x = 0;
    for (; x + kFloatLanes <= columns; x += kFloatLanes) {
      const auto value = load_lanes<Floats4>(row + x);
      store_lanes(lows + x, floats_min(load_lanes<Floats4>(lows + x), value));
      store_lanes(highs + x, floats_max(load_lanes<Floats4>(highs + x), value));
    }
    for (; x < columns; ++x) {
      lows[x] = std::min(lows[x], row[x]);
      highs[x] = std::max(highs[x], row[x]);
    }
  }
  constexpr int kCoarsePerTile = kTileWidth / 2;
  for (int tile = 0; tile < tile_count(width); ++tile) {
    const int from = std::min(tile * kCoarsePerTile, last_column);
    const int to = std::min(from + kCoarsePerTile - 1, last_column);
    const int left = std::max(from - 1, 0);
    const int right = std::min(to + 1, last_column);
    const float smallest = *std::min_element(lows + left, lows + right + 1);
    const float largest = *std::max_element(highs + left, highs + right + 1);
    low[static_cast<std::size_t>(tile)] = 2 * floor_of(smallest) - band;
    high[static_cast<std::size_t>(tile)] = 2 * ceiling_of(largest) + band;
  }
}

} // namespace marsokhod::nav::detail
