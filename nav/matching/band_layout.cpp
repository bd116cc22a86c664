// Laying out a band's tiles and their disparity windows (private to the stereo matcher).

#include "matching/band_layout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace marsokhod::nav::detail {

BandLayout::BandLayout(std::pmr::memory_resource* memory)
    : first_(memory), cells_(memory), offset_(memory) {}

void BandLayout::lay_out(int width, DisparityLimits limits, std::span<const int> wanted_low,
                         std::span<const int> wanted_high) {
  width_ = width;
  limits_ = limits;
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

void BandLayout::check() const {
  const int tiles = tile_count(width_);
  if (first_.size() != static_cast<std::size_t>(tiles) || offset_.empty() || offset_[0] != 0)
    throw std::range_error("matching: a band's layout was struck");
  for (std::size_t t = 0; t < first_.size(); ++t) {
    const int pixels = std::min(kTileWidth, width_ - static_cast<int>(t) * kTileWidth);
    // As lay_out leaves it: from the low limit to the high one or the tile's last column.
    const int reach = std::min(limits_.high, static_cast<int>(t) * kTileWidth + pixels - 1);
    const long long last = static_cast<long long>(first_[t]) + cells_[t] - 1;
    const bool inside =
        first_[t] >= limits_.low && cells_[t] >= 1 && last <= std::max(limits_.low, reach);
    if (!inside || offset_[t + 1] != offset_[t] + static_cast<std::size_t>(pixels * cells_[t]))
      throw std::range_error(fmt::format("matching: tile {} of a band's layout was struck", t));
  }
}

} // namespace marsokhod::nav::detail
