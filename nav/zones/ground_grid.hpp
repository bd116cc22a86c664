// The ground grid of visible points (private to the zone rules).
#pragma once

// The visible points binned into a square grid on the level ground plane (no interpolation:
// a cell holds the points that fall into it, or nothing), so that the zone rules can measure
// "within 0.30 m" on the ground whatever the perspective. Private to the zone rules.

#include "zones/zone_buffer.hpp"

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include <cstdint>
#include <limits>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// Visible points binned into square cells on the ground, with each cell's height extremes.
class GroundGrid {
public:
  /// Bins every pixel whose `zone` (channel 0) is not Zone::unknown and that is known and within
  /// `max_range_m`; the grid spans just those points, `cell_m` a side. `work` counts the points
  /// binned.
  GroundGrid(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone, double cell_m,
             double max_range_m, std::pmr::memory_resource* memory, std::uint64_t& work);

  int nx() const { return nx_; } ///< cells along the forward axis
  int ny() const { return ny_; } ///< cells along the lateral axis
  double cell() const { return cell_; }
  bool empty() const { return nx_ == 0 || ny_ == 0; }

  /// Cell of a pixel's ground point, or -1 when the pixel was not binned.
  int cell_of(int x, int y) const { return cells_of_row(y)[x]; }
  /// cell_of for the pixels of row y, in order.
  const std::int32_t* cells_of_row(int y) const { return pixel_cell_.data() + row_start(y); }
  int index(int ix, int iy) const { return iy * nx_ + ix; }
  bool inside(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < nx_ && iy < ny_; }

  /// Highest and lowest elevation of each cell; -inf (highest) and +inf (lowest) for an empty
  /// cell, so that an empty cell never decides a maximum or a minimum.
  const std::pmr::vector<float>& highest() const { return highest_; }
  const std::pmr::vector<float>& lowest() const { return lowest_; }
  /// Mean elevation of a cell (NaN when empty) and its number of points.
  float mean(int i) const {
    return count_[static_cast<std::size_t>(i)] > 0
               ? sum_[static_cast<std::size_t>(i)] / count_[static_cast<std::size_t>(i)]
               : kNoHeight;
  }
  int count(int i) const { return count_[static_cast<std::size_t>(i)]; }
  const std::pmr::vector<std::int32_t>& counts() const { return count_; } ///< count() of each cell

  static constexpr float kNoHeight = std::numeric_limits<float>::quiet_NaN();

private:
  void bin(const TerrainRows& terrain, const float (&origin)[2], std::uint64_t& work);
  std::size_t row_start(int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
  }
  std::int32_t* binned_row(int y) { return pixel_cell_.data() + row_start(y); }

  double x0_ = 0.0;
  double y0_ = 0.0;
  double cell_ = 0.1;
  int nx_ = 0;
  int ny_ = 0;
  int width_ = 0;
  ScratchBuffer<std::int32_t> pixel_cell_; // a cell or -1 per pixel, row by row
  std::pmr::vector<float> highest_;
  std::pmr::vector<float> lowest_;
  std::pmr::vector<float> sum_;
  std::pmr::vector<std::int32_t> count_;
};

} // namespace marsokhod::nav::detail
