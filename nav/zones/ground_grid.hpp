// The ground grid of visible points (private to the zone rules).
#pragma once

// The visible points binned into a square grid on the level ground plane (no interpolation:
// a cell holds the points that fall into it, or nothing), so that the zone rules can measure
// "within 0.30 m" on the ground whatever the perspective. The grid spans the binned points
// (the lattice); a GroundGrid holds all its columns, or a strip of them along the forward axis
// with the halo of columns the rules read around it, when memory holds no more. Private to the
// zone rules.

#include "zones/zone_buffer.hpp"
#include "zones/zone_lattice.hpp"

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include <cstdint>
#include <limits>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// The cells of the lattice a GroundGrid holds: columns (forward cells) lo..hi - 1, of which
/// own_begin..own_end - 1 are its own and the rest a halo the rules of its own ones read.
struct GridColumns {
  int lo = 0;
  int hi = 0;
  int own_begin = 0;
  int own_end = 0;
};

/// Visible points binned into square cells on the ground, with each cell's height extremes.
class GroundGrid {
public:
  /// Bins every pixel whose `zone` (channel 0) is not Zone::unknown and that is known and within
  /// `max_range_m`; the grid spans just those points, `cell_m` a side, and keeps every pixel's
  /// cell. `work` counts the points binned, twice.
  GroundGrid(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone, double cell_m,
             double max_range_m, std::pmr::memory_resource* memory, std::uint64_t& work);
  /// Bins the same pixels' points that fall into `columns` of `lattice` (from
  /// ground_lattice()); `zone` is single-channel. Pixel cells are worked out again by
  /// row_cells(). `work` counts the points of the own columns twice, `halo_work` the others.
  GroundGrid(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone,
             const GroundLattice& lattice, const GridColumns& columns,
             std::pmr::memory_resource* memory, std::uint64_t& work, std::uint64_t& halo_work);

  int nx() const { return nx_; } ///< cells along the forward axis
  int ny() const { return ny_; } ///< cells along the lateral axis
  double cell() const { return lattice_.along.cell; }
  bool empty() const { return nx_ == 0 || ny_ == 0; }
  /// The own columns, as this grid's columns.
  int own_begin() const { return own_begin_; }
  int own_end() const { return own_end_; }
  bool owns(int ix) const { return ix >= own_begin_ && ix < own_end_; }

  /// cell_of for the pixels of row y, in order, when the grid keeps them (the first
  /// constructor).
  const std::int32_t* cells_of_row(int y) const { return pixel_cell_.data() + row_start(y); }
  /// The cell of each pixel of row y (-1 when not binned or outside the grid's columns): the
  /// kept ones, or worked out again into `scratch` (width entries) from the terrain row and
  /// the zone row.
  const std::int32_t* row_cells(int y, const TerrainRows::Row& points, const std::uint8_t* zone,
                                std::int32_t* scratch) const;
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
  void allocate_cells();
  void bin_kept(const TerrainRows& terrain, std::uint64_t& work);
  std::size_t row_start(int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
  }

  GroundLattice lattice_;
  int lo_ = 0;
  int nx_ = 0;
  int ny_ = 0;
  int own_begin_ = 0;
  int own_end_ = 0;
  int width_ = 0;
  ScratchBuffer<std::int32_t> pixel_cell_; // a cell or -1 per pixel, row by row, when kept
  std::pmr::vector<float> highest_;
  std::pmr::vector<float> lowest_;
  std::pmr::vector<float> sum_;
  std::pmr::vector<std::int32_t> count_;
};

/// The lattice of the points GroundGrid bins: one pass over the rows.
GroundLattice ground_lattice(const TerrainRows& terrain,
                             imaging::ImageView<const std::uint8_t> zone, double cell_m,
                             double max_range_m, std::pmr::memory_resource* memory);

} // namespace marsokhod::nav::detail
