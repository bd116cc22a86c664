#include "band_layout.hpp"

#include <algorithm>

namespace marsokhod::nav::detail {
namespace {

// out = extreme of in over the 3x3 neighbourhood (borders repeated), separably.
template <class Pick>
void extreme3x3(const Image<std::int32_t>& in, Image<std::int32_t>& across,
                Image<std::int32_t>& out, Pick pick) {
  const int width = in.width();
  const int height = in.height();
  for (int y = 0; y < height; ++y) {
    const std::int32_t* row = in.row(y);
    std::int32_t* target = across.row(y);
    target[0] = pick(row[0], row[std::min(1, width - 1)]);
    for (int x = 1; x + 1 < width; ++x)
      target[x] = pick(pick(row[x - 1], row[x]), row[x + 1]);
    if (width > 1)
      target[width - 1] = pick(row[width - 2], row[width - 1]);
  }
  for (int y = 0; y < height; ++y) {
    const std::int32_t* above = across.row(std::max(y - 1, 0));
    const std::int32_t* middle = across.row(y);
    const std::int32_t* below = across.row(std::min(y + 1, height - 1));
    std::int32_t* target = out.row(y);
    for (int x = 0; x < width; ++x)
      target[x] = pick(pick(above[x], middle[x]), below[x]);
  }
}

} // namespace

BandLayout::BandLayout(std::pmr::memory_resource* memory)
    : first_(memory), cells_(memory), offset_(memory) {}

void BandLayout::lay_out(int width, DisparityLimits limits, std::span<const int> wanted_low,
                         std::span<const int> wanted_high) {
  width_ = width;
  const int tiles = tile_count(width);
  first_.resize(static_cast<std::size_t>(tiles));
  cells_.resize(static_cast<std::size_t>(tiles));
  offset_.resize(static_cast<std::size_t>(tiles) + 1);
  offset_[0] = 0;
  for (std::size_t t = 0; t < static_cast<std::size_t>(tiles); ++t) {
    const int pixels = std::min(kTileWidth, width - static_cast<int>(t) * kTileWidth);
    // No pixel of the tile reaches a right pixel beyond its own column: x - d >= 0.
    const int reach = std::min(limits.high, static_cast<int>(t) * kTileWidth + pixels - 1);
    int low = std::max(wanted_low[t], limits.low);
    int high = std::min(wanted_high[t], reach);
    if (high < low)
      low = high = std::clamp(wanted_low[t], limits.low, std::max(limits.low, reach));
    first_[t] = low;
    cells_[t] = high - low + 1;
    offset_[t + 1] = offset_[t] + static_cast<std::size_t>(pixels * cells_[t]);
  }
}

CoarseGuide::CoarseGuide(ImageView<const float> coarse, std::pmr::memory_resource* memory)
    : low_(coarse.width(), coarse.height(), 1, 0, memory),
      high_(coarse.width(), coarse.height(), 1, 0, memory) {
  Image<std::int32_t> floor_image(coarse.width(), coarse.height(), 1, 0, memory);
  Image<std::int32_t> ceiling_image(coarse.width(), coarse.height(), 1, 0, memory);
  for (int y = 0; y < coarse.height(); ++y) {
    const float* row = coarse.row(y);
    std::int32_t* floors = floor_image.row(y);
    std::int32_t* ceilings = ceiling_image.row(y);
    for (int x = 0; x < coarse.width(); ++x) {
      // Disparities are never negative: truncation is the floor.
      const auto whole = static_cast<std::int32_t>(row[x]);
      floors[x] = whole;
      ceilings[x] = whole + (static_cast<float>(whole) < row[x] ? 1 : 0);
    }
  }
  Image<std::int32_t> across(coarse.width(), coarse.height(), 1, 0, memory);
  extreme3x3(floor_image, across, low_,
             [](std::int32_t a, std::int32_t b) { return std::min(a, b); });
  extreme3x3(ceiling_image, across, high_,
             [](std::int32_t a, std::int32_t b) { return std::max(a, b); });
}

void CoarseGuide::wanted(int y0, int width, int band, std::span<int> low,
                         std::span<int> high) const {
  const int last_column = low_.width() - 1;
  const int first_row = std::min(y0 / 2, low_.height() - 1);
  const int last_row = std::min((y0 + kBandRows - 1) / 2, low_.height() - 1);
  constexpr int kCoarsePerTile = kTileWidth / 2;
  for (int tile = 0; tile < tile_count(width); ++tile) {
    const int from = std::min(tile * kCoarsePerTile, last_column);
    const int to = std::min(from + kCoarsePerTile - 1, last_column);
    int smallest = low_(from, first_row);
    int largest = high_(from, first_row);
    for (int y = first_row; y <= last_row; ++y) {
      const std::int32_t* lows = low_.row(y);
      const std::int32_t* highs = high_.row(y);
      for (int x = from; x <= to; ++x) {
        smallest = std::min(smallest, lows[x]);
        largest = std::max(largest, highs[x]);
      }
    }
    low[static_cast<std::size_t>(tile)] = 2 * smallest - band;
    high[static_cast<std::size_t>(tile)] = 2 * largest + band;
  }
}

} // namespace marsokhod::nav::detail
