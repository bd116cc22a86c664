// MatchingCost: a band's 3x3 window costs at each disparity (private to the stereo matcher).
#pragma once

// Matching costs of a band of scan lines (private to the stereo matcher).

#include "matching/band_columns.hpp"
#include "matching/band_layout.hpp"

#include "marsokhod/nav/features/layer_features.hpp"

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
  void load_band(const LayerFeatures& left, const LayerFeatures& right, int y0,
                 const BandLayout& layout);

  /// Fills costs (layout.total() cells of kBandRows lanes) for the band; returns the column
  /// distances computed (per line).
  std::uint64_t compute(const BandLayout& layout, std::uint16_t* costs);

private:
  template <class Distance>
  std::uint64_t compute_with(const BandLayout& layout, std::uint16_t* costs);
  template <class Distance>
  void tile_costs(const BandLayout& layout, int first_pixel, int pixels, std::uint16_t* costs);

  FeatureKind kind_;
  int width_;
  int pad_;           // right columns exist from x = -pad_
  BandColumns left_;  // x = -1 .. width
  BandColumns right_; // x = -pad_ .. width
};

/// The cost of a cell that is not a candidate: higher than any path through candidates can
/// cost, so it is never chosen and never feeds a neighbour.
inline constexpr std::uint16_t kPaddingCost = 1023;

} // namespace marsokhod::nav::detail
