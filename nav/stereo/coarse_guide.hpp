// Search windows from the coarser layer's disparities (private to the stereo matcher).
#pragma once

// The coarser layer's disparities as the search windows of the next finer layer (private to
// the stereo matcher).

#include "marsokhod/imaging/image/image.hpp"

#include <cstdint>
#include <memory_resource>
#include <span>

namespace marsokhod::nav::detail {

/// The coarser layer's disparities (finite, not negative) as initial shifts for the next finer
/// layer: a tile of the finer layer searches twice the smallest to twice the largest coarse
/// disparity of the coarse pixels under it and their 3x3 neighbours, widened by `band` on each
/// side. Taking the neighbourhood rather than one coarse pixel keeps both sides of a depth edge
/// in reach.
class CoarseGuide {
public:
  /// `coarse` must outlive the guide.
  CoarseGuide(imaging::ImageView<const float> coarse, std::pmr::memory_resource* memory);

  /// Wanted ranges of the tiles of the band whose first row is y0 (finer layer, width pixels).
  void wanted(int y0, int width, int band, std::span<int> low, std::span<int> high);
  /// Coarse pixels the guide reads.
  std::uint64_t pixels() const {
    return static_cast<std::uint64_t>(coarse_.width()) *
           static_cast<std::uint64_t>(coarse_.height());
  }

private:
  imaging::ImageView<const float> coarse_;
  // The smallest and largest disparity of each coarse column over the band's rows.
  std::pmr::vector<float> column_low_;
  std::pmr::vector<float> column_high_;
};

} // namespace marsokhod::nav::detail
