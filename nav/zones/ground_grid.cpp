// Binning the visible terrain points into the ground grid the zone rules measure on.

#include "zones/ground_grid.hpp"

#include "lanes/simd_lanes.hpp"
#include "zones/zone_bounds.hpp"
#include "zones/zone_bytes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

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

// The lattice cell of the pixels of a row marked kBinned, four at a time where SSE2 is there;
// the others keep kNotBinned. A lane that is not binned is moved to the lattice's origin, a
// binned point, so that no lane converts an infinity; four pixels none of which is binned are
// passed over.
void lattice_cells(const TerrainRows::Row& row, const GroundLattice& lattice, int width,
                   std::int32_t* cells) {
  const LatticeAxis& along = lattice.along;
  const LatticeAxis& across = lattice.across;
  int x = 0;
#ifdef __SSE2__
  const LatticeLanes along_lanes(along);
  const LatticeLanes across_lanes(across);
  const __m128 origin_x = _mm_set1_ps(lattice.origin[0]);
  const __m128 origin_y = _mm_set1_ps(lattice.origin[1]);
  const __m128i nx = _mm_set1_epi32(along.n);
  for (; x + kFloatLanes <= width; x += kFloatLanes) {
    const __m128i in = _mm_cmpeq_epi32(load_lanes<__m128i>(cells + x), _mm_set1_epi32(kBinned));
    if (_mm_movemask_ps(_mm_castsi128_ps(in)) == 0)
      continue;
    const __m128 mask = _mm_castsi128_ps(in);
    const __m128 px =
        _mm_or_ps(_mm_and_ps(mask, _mm_loadu_ps(row.forward + x)), _mm_andnot_ps(mask, origin_x));
    const __m128 py =
        _mm_or_ps(_mm_and_ps(mask, _mm_loadu_ps(row.left + x)), _mm_andnot_ps(mask, origin_y));
    const __m128i index =
        _mm_add_epi32(multiply_lanes(across_lanes.cells_of(py), nx), along_lanes.cells_of(px));
    store_lanes(cells + x, _mm_or_si128(index, _mm_xor_si128(in, _mm_set1_epi32(-1))));
  }
#endif
  for (; x < width; ++x)
    if (cells[x] == kBinned)
      cells[x] = across.cell_of(row.left[x]) * along.n + along.cell_of(row.forward[x]);
}

// The lattice of the binned points' bounds: the first point sits in the middle of its cell, so
// points on a regular lattice of the cell's pitch fall into cells one to one.
GroundLattice lattice_of(const GroundBounds& b, double cell, float max_range) {
  GroundLattice lattice;
  lattice.along.cell = cell;
  lattice.across.cell = cell;
  lattice.max_range = max_range;
  if (b.empty())
    return lattice;
  const double x0 = b.min_x - 0.5 * cell;
  const double y0 = b.min_y - 0.5 * cell;
  lattice.along = {x0, cell, static_cast<int>(std::floor((b.max_x - x0) / cell)) + 1};
  lattice.across = {y0, cell, static_cast<int>(std::floor((b.max_y - y0) / cell)) + 1};
  lattice.origin[0] = b.min_x;
  lattice.origin[1] = b.min_y;
  return lattice;
}

} // namespace

GroundLattice ground_lattice(const TerrainRows& terrain,
                             imaging::ImageView<const std::uint8_t> zone, double cell_m,
                             double max_range_m, std::pmr::memory_resource* memory) {
  ScratchBuffer<std::int32_t> row(static_cast<std::size_t>(terrain.width()), memory);
  const auto max_range = static_cast<float>(max_range_m);
  return lattice_of(mark_binned(terrain, zone, max_range, row.data(), 0), cell_m, max_range);
}

GroundGrid::GroundGrid(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone,
                       double cell_m, double max_range_m, std::pmr::memory_resource* memory,
                       std::uint64_t& work)
    : width_(terrain.width()),
      pixel_cell_(static_cast<std::size_t>(terrain.width()) * terrain.height(), memory),
      highest_(memory), lowest_(memory), sum_(memory), count_(memory) {
  const imaging::Image<std::uint8_t> own =
      zone.channels() == 1 ? imaging::Image<std::uint8_t>(memory) : first_channel(zone, memory);
  const auto max_range = static_cast<float>(max_range_m);
  const GroundBounds b = mark_binned(terrain, zone.channels() == 1 ? zone : own.view(), max_range,
                                     pixel_cell_.data(), width_);
  lattice_ = lattice_of(b, cell_m, max_range);
  if (lattice_.empty()) {
    std::fill(pixel_cell_.data(), pixel_cell_.data() + pixel_cell_.size(), kNotBinned);
    return;
  }
  nx_ = lattice_.along.n;
  ny_ = lattice_.across.n;
  own_end_ = nx_;
  bin_kept(terrain, work);
}

GroundGrid::GroundGrid(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone,
                       const GroundLattice& lattice, const GridColumns& columns,
                       std::pmr::memory_resource* memory, std::uint64_t& work,
                       std::uint64_t& halo_work)
    : lattice_(lattice), lo_(columns.lo), nx_(columns.hi - columns.lo), ny_(lattice.across.n),
      own_begin_(columns.own_begin - columns.lo), own_end_(columns.own_end - columns.lo),
      width_(terrain.width()), pixel_cell_(memory), highest_(memory), lowest_(memory), sum_(memory),
      count_(memory) {
  if (lattice.empty())
    return;
  allocate_cells();
  const CellSums sums{highest_.data(), lowest_.data(), sum_.data(), count_.data()};
  ScratchBuffer<std::int32_t> cells(static_cast<std::size_t>(width_), memory);
  std::uint64_t own = 0;
  std::uint64_t halo = 0;
  for (int y = 0; y < terrain.height(); ++y) {
    const TerrainRows::Row points = terrain.row(y);
    const std::int32_t* row = row_cells(y, points, zone.row(y), cells.data());
    for (int x = 0; x < width_; ++x) {
      if (row[x] < 0)
        continue;
      sums.add(row[x], points.elevation[x]);
      ++(owns(row[x] % nx_) ? own : halo);
    }
  }
  work += 2 * own;
  halo_work += 2 * halo;
}

void GroundGrid::allocate_cells() {
  const auto size = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  highest_.assign(size, -kInfinity);
  lowest_.assign(size, kInfinity);
  sum_.assign(size, 0.0F);
  count_.assign(size, 0);
}

// A cell's sum takes its points row by row, left to right.
void GroundGrid::bin_kept(const TerrainRows& terrain, std::uint64_t& work) {
  allocate_cells();
  const CellSums sums{highest_.data(), lowest_.data(), sum_.data(), count_.data()};
  std::uint64_t points = 0;
  for (int y = 0; y < terrain.height(); ++y) {
    const TerrainRows::Row row = terrain.row(y);
    std::int32_t* cells = pixel_cell_.data() + row_start(y);
    lattice_cells(row, lattice_, width_, cells);
    for (int x = 0; x < width_; ++x)
      if (cells[x] >= 0) {
        sums.add(cells[x], row.elevation[x]);
        ++points;
      }
  }
  work += 2 * points;
}

const std::int32_t* GroundGrid::row_cells(int y, const TerrainRows::Row& points,
                                          const std::uint8_t* zone, std::int32_t* scratch) const {
  if (pixel_cell_.size() != 0)
    return cells_of_row(y);
  mark_binned_row(zone, points.elevation, points.range, lattice_.max_range, width_, scratch);
  lattice_cells(points, lattice_, width_, scratch);
  const int columns = lattice_.along.n;
  for (int x = 0; x < width_; ++x) {
    if (scratch[x] < 0)
      continue;
    const int ix = scratch[x] % columns - lo_;
    scratch[x] = ix >= 0 && ix < nx_ ? index(ix, scratch[x] / columns) : kNotBinned;
  }
  return scratch;
}

} // namespace marsokhod::nav::detail
