#pragma once

// Matching costs of a band of scan lines (private to the stereo matcher).

#include "band_layout.hpp"

#include "marsokhod/nav/brightness_features.hpp"
#include "marsokhod/nav/image.hpp"

#include <array>
#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// The cost of a left pixel (x, y) at disparity d is the sum, over the 3x3 correlation window,
/// of the feature distances between left pixel (x+i, y+j) and right pixel (x+i-d, y+j). A
/// window is summed from column distances (the three pixels of one column of the window
/// compared at once, the band's eight lines in the eight lanes): each tile compares every
/// column any of its windows covers once per disparity of its window. Disparities beyond a
/// pixel's reach (x - d < 0) get kPaddingCost.
class MatchingCost {
public:
  MatchingCost(FeatureKind kind, int width, int max_disparity, std::pmr::memory_resource* memory);

  /// Loads the band whose first row is y0 (rows past the layer repeat its last row): the
  /// columns the layout's windows meet.
  void load_band(const Image<std::uint32_t>& left, const Image<std::uint32_t>& right, int y0,
                 const BandLayout& layout);

  /// Fills costs (layout.total() cells of kBandRows lanes) for the band; returns the column
  /// distances computed (per line).
  std::uint64_t compute(const BandLayout& layout, std::uint16_t* costs);

private:
  // A column is up to five 16-bit words: census3x3 packs its three bytes into two words, the
  // 24-bit census5x5 needs five, the ranks of rank5x5 take one word per row.
  static constexpr int kMaxWords = 5;

  template <class Distance>
  std::uint64_t compute_with(const BandLayout& layout, std::uint16_t* costs);
  template <class Distance>
  void tile_costs(const BandLayout& layout, int first_pixel, int pixels, std::uint16_t* costs);

  FeatureKind kind_;
  int width_;
  int pad_; // right columns exist from x = -pad_
  int right_columns_;
  // Column words by word, then column (left: x + 1 for x = -1..width; right: x + pad_ for
  // x = -pad_..width), then lane.
  std::array<std::pmr::vector<std::uint16_t>, kMaxWords> left_;
  std::array<std::pmr::vector<std::uint16_t>, kMaxWords> right_;
  // Column distances of one tile: kTileWidth + 2 columns by the tile's cells, by lane.
  std::pmr::vector<std::uint16_t> column_cost_;
};

/// The cost of a cell that is not a candidate: higher than any path through candidates can
/// cost, so it is never chosen and never feeds a neighbour.
inline constexpr std::uint16_t kPaddingCost = 1023;

} // namespace marsokhod::nav::detail
