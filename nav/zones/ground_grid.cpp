// Binning the visible terrain points into the ground grid the zone rules measure on.

#include "zones/ground_grid.hpp"

#include "lanes/simd_lanes.hpp"
#include "zones/zone_bounds.hpp"
#include "zones/zone_lattice.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Channel 0 of a zone map: find_zones' own map already is one.
imaging::Image<std::uint8_t> first_channel(imaging::ImageView<const std::uint8_t> zone,
                                           std::pmr::memory_resource* memory) {
  imaging::Image<std::uint8_t> out(zone.width(), zone.height(), 1, 0, memory);
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x)
      out(x, y) = zone(x, y);
  return out;
}

// The cells' statistics, held in locals so that the stores to them are not read as stores to
// the grid's own members.
struct CellSums {
  float* highest;
  float* lowest;
  float* sum;
  std::int32_t* count;

  void add(std::int32_t cell, float h) const {
    const auto i = static_cast<std::size_t>(cell);
    highest[i] = std::max(highest[i], h);
    lowest[i] = std::min(lowest[i], h);
    sum[i] += h;
    ++count[i];
  }
};

// Bins the pixels of a row marked kBinned, in order (a cell's sum takes its points row by row,
// left to right), four at a time where SSE2 is there; returns how many. A lane that is not
// binned is moved to `origin`, a binned point, so that no lane converts an infinity; four pixels
// none of which is binned are passed over.
std::uint64_t bin_row(const float* forward, const float* left, const float* elevation,
                      const LatticeAxis& along, const LatticeAxis& across, const float (&origin)[2],
                      int width, std::int32_t* cells, const CellSums& sums) {
  std::uint64_t points = 0;
  int x = 0;
#ifdef __SSE2__
  const LatticeLanes along_lanes(along);
  const LatticeLanes across_lanes(across);
  const __m128 origin_x = _mm_set1_ps(origin[0]);
  const __m128 origin_y = _mm_set1_ps(origin[1]);
  const __m128i nx = _mm_set1_epi32(along.n);
  for (; x + kFloatLanes <= width; x += kFloatLanes) {
    const __m128i in = _mm_cmpeq_epi32(load_lanes<__m128i>(cells + x), _mm_set1_epi32(kBinned));
    unsigned lanes = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(in)));
    if (lanes == 0)
      continue;
    const __m128 mask = _mm_castsi128_ps(in);
    const __m128 px =
        _mm_or_ps(_mm_and_ps(mask, _mm_loadu_ps(forward + x)), _mm_andnot_ps(mask, origin_x));
    const __m128 py =
        _mm_or_ps(_mm_and_ps(mask, _mm_loadu_ps(left + x)), _mm_andnot_ps(mask, origin_y));
    const __m128i index =
        _mm_add_epi32(multiply_lanes(across_lanes.cells_of(py), nx), along_lanes.cells_of(px));
    store_lanes(cells + x, _mm_or_si128(index, _mm_xor_si128(in, _mm_set1_epi32(-1))));
    for (; lanes != 0; lanes &= lanes - 1, ++points) {
      const int lane = std::countr_zero(lanes);
      sums.add(cells[x + lane], elevation[x + lane]);
    }
  }
#endif
  for (; x < width; ++x) {
    if (cells[x] != kBinned)
      continue;
    cells[x] = across.cell_of(left[x]) * along.n + along.cell_of(forward[x]);
    sums.add(cells[x], elevation[x]);
    ++points;
  }
  return points;
}

} // namespace

GroundGrid::GroundGrid(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone,
                       double cell_m, double max_range_m, std::pmr::memory_resource* memory,
                       std::uint64_t& work)
    : cell_(cell_m), width_(terrain.width()),
      pixel_cell_(static_cast<std::size_t>(terrain.width()) * terrain.height(), memory),
      highest_(memory), lowest_(memory), sum_(memory), count_(memory) {
  const imaging::Image<std::uint8_t> own =
      zone.channels() == 1 ? imaging::Image<std::uint8_t>(memory) : first_channel(zone, memory);
  const GroundBounds b = mark_binned(terrain, zone.channels() == 1 ? zone : own.view(),
                                     static_cast<float>(max_range_m), pixel_cell_.data());
  if (b.empty()) {
    std::fill(pixel_cell_.data(), pixel_cell_.data() + pixel_cell_.size(), kNotBinned);
    return;
  }
  // The first point sits in the middle of its cell, so points on a regular lattice of the
  // cell's pitch fall into cells one to one.
  x0_ = b.min_x - 0.5 * cell_;
  y0_ = b.min_y - 0.5 * cell_;
  nx_ = static_cast<int>(std::floor((b.max_x - x0_) / cell_)) + 1;
  ny_ = static_cast<int>(std::floor((b.max_y - y0_) / cell_)) + 1;
  bin(terrain, {b.min_x, b.min_y}, work);
}

void GroundGrid::bin(const TerrainRows& terrain, const float (&origin)[2], std::uint64_t& work) {
  const auto size = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  highest_.assign(size, -kInfinity);
  lowest_.assign(size, kInfinity);
  sum_.assign(size, 0.0F);
  count_.assign(size, 0);
  const LatticeAxis along{x0_, cell_, nx_};
  const LatticeAxis across{y0_, cell_, ny_};
  const CellSums sums{highest_.data(), lowest_.data(), sum_.data(), count_.data()};
  std::uint64_t points = 0;
  for (int y = 0; y < terrain.height(); ++y) {
    const TerrainRows::Row row = terrain.row(y);
    points += bin_row(row.forward, row.left, row.elevation, along, across, origin, terrain.width(),
                      binned_row(y), sums);
  }
  work += 2 * points;
}

} // namespace marsokhod::nav::detail
