// The pixels the ground grid bins and their bounds (private to the zones' ground grid).
#pragma once

// Which pixels the ground grid bins, and how far their points reach (private to
// ground_grid.cpp): one pass over the terrain, four pixels at a time where SSE2 is there.

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace marsokhod::nav::detail {

/// A pixel's entry before binning: binned or not.
inline constexpr std::int32_t kBinned = 0;
inline constexpr std::int32_t kNotBinned = -1;

/// The extent of a set of ground points; a NaN coordinate is passed over, as std::min and
/// std::max pass it over.
struct GroundBounds {
  float min_x = std::numeric_limits<float>::infinity();
  float max_x = -std::numeric_limits<float>::infinity();
  float min_y = std::numeric_limits<float>::infinity();
  float max_y = -std::numeric_limits<float>::infinity();

  bool empty() const { return min_x > max_x; }
  void take(float x, float y) { take(GroundBounds{x, x, y, y}); }
  void take(const GroundBounds& other) {
    min_x = std::min(min_x, other.min_x);
    max_x = std::max(max_x, other.max_x);
    min_y = std::min(min_y, other.min_y);
    max_y = std::max(max_y, other.max_y);
  }
};

/// Writes kBinned for the pixels of the single-channel `zone` that are not Zone::unknown, known
/// and within `max_range` (a NaN range is not), kNotBinned for the others, row by row into
/// `binned`; returns the bounds of the binned points. The order the points are taken in does not
/// matter: only a tie of +0 and -0 could tell, and the grid's origin and size come out the same
/// for both.
/// Row y's entries go to binned + y * row_stride (a stride of 0 reuses one row).
GroundBounds mark_binned(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone,
                         float max_range, std::int32_t* binned, std::ptrdiff_t row_stride);

/// mark_binned for one row, without the bounds.
void mark_binned_row(const std::uint8_t* zone, const float* elevation, const float* range,
                     float max_range, int width, std::int32_t* binned);

} // namespace marsokhod::nav::detail
