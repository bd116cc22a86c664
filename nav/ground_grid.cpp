#include "ground_grid.hpp"

#include "simd_lanes.hpp"
#include "zone_lattice.hpp"

#include "marsokhod/nav/zones.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kLargest = std::numeric_limits<float>::max();
constexpr std::int32_t kBinned = 0;
constexpr std::int32_t kNotBinned = -1;

// Channel 0 of a zone map: find_zones' own map already is one.
Image<std::uint8_t> first_channel(ImageView<const std::uint8_t> zone,
                                  std::pmr::memory_resource* memory) {
  Image<std::uint8_t> out(zone.width(), zone.height(), 1, 0, memory);
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x)
      out(x, y) = zone(x, y);
  return out;
}

// A pixel is binned when it is judged, known and within range (NaN ranges fail the test):
// kBinned or kNotBinned per pixel, branch-free (& rather than &&) so that the loop vectorises.
void mark_binned(const std::uint8_t* zone, const float* elevation, const float* range,
                 float max_range, int width, std::int32_t* out) {
  const auto unknown = static_cast<std::uint8_t>(Zone::unknown);
  for (int x = 0; x < width; ++x) {
    const bool binned =
        (zone[x] != unknown) & (std::fabs(elevation[x]) <= kLargest) & (range[x] <= max_range);
    out[x] = binned ? kBinned : kNotBinned;
  }
}

// `value` where `mask` is set, `otherwise` elsewhere.
Floats4 select_lanes(Ints4 mask, Floats4 value, float otherwise) {
  const Ints4 other = std::bit_cast<Ints4>(Floats4{} + otherwise);
  return std::bit_cast<Floats4>((std::bit_cast<Ints4>(value) & mask) | (other & ~mask));
}

struct Bounds {
  float min_x = kInfinity;
  float max_x = -kInfinity;
  float min_y = kInfinity;
  float max_y = -kInfinity;
  bool empty() const { return min_x > max_x; }

  // std::min and std::max keep the bound when the point is NaN; so do the lanes below.
  void take(float x, float y) {
    min_x = std::min(min_x, x);
    max_x = std::max(max_x, x);
    min_y = std::min(min_y, y);
    max_y = std::max(max_y, y);
  }
  void take(const Bounds& other) {
    min_x = std::min(min_x, other.min_x);
    max_x = std::max(max_x, other.max_x);
    min_y = std::min(min_y, other.min_y);
    max_y = std::max(max_y, other.max_y);
  }
};

// Bounds over four lanes at a time; a point that is not binned stands as +inf to the minima
// and -inf to the maxima. The order the points are taken in does not matter: only a tie of
// +0 and -0 could tell, and the grid's origin and size come out the same for both.
class BoundLanes {
public:
  void take(const std::int32_t* binned, const float* forward, const float* left) {
    const Ints4 in = load_lanes<Ints4>(binned) == kBinned;
    const Floats4 x = load_lanes<Floats4>(forward);
    const Floats4 y = load_lanes<Floats4>(left);
    min_x_ = floats_min(select_lanes(in, x, kInfinity), min_x_);
    max_x_ = floats_max(max_x_, select_lanes(in, x, -kInfinity));
    min_y_ = floats_min(select_lanes(in, y, kInfinity), min_y_);
    max_y_ = floats_max(max_y_, select_lanes(in, y, -kInfinity));
  }
  Bounds fold() const {
    Bounds b;
    for (int lane = 0; lane < kFloatLanes; ++lane)
      b.take(Bounds{min_x_[lane], max_x_[lane], min_y_[lane], max_y_[lane]});
    return b;
  }

private:
  Floats4 min_x_ = Floats4{} + kInfinity;
  Floats4 max_x_ = Floats4{} - kInfinity;
  Floats4 min_y_ = Floats4{} + kInfinity;
  Floats4 max_y_ = Floats4{} - kInfinity;
};

Bounds bounds_of(const TerrainPoints& terrain, const std::int32_t* binned) {
  BoundLanes lanes;
  Bounds tail;
  const int width = terrain.width();
  for (int y = 0; y < terrain.height(); ++y) {
    const std::int32_t* in = binned + static_cast<std::ptrdiff_t>(y) * width;
    const float* forward = terrain.forward.row(y);
    const float* left = terrain.left.row(y);
    int x = 0;
    for (; x + kFloatLanes <= width; x += kFloatLanes)
      lanes.take(in + x, forward + x, left + x);
    for (; x < width; ++x)
      if (in[x] == kBinned)
        tail.take(forward[x], left[x]);
  }
  Bounds b = lanes.fold();
  b.take(tail);
  return b;
}

// The cell of each binned pixel of a row (the others stay kNotBinned), four at a time where
// SSE2 is there. A lane that is not binned is moved to `origin`, a binned point, so that no lane
// converts an infinity; four pixels none of which is binned are passed over.
void bin_row(const float* forward, const float* left, const LatticeAxis& along,
             const LatticeAxis& across, const float (&origin)[2], int width, std::int32_t* cells) {
  int x = 0;
#ifdef __SSE2__
  const LatticeLanes along_lanes(along);
  const LatticeLanes across_lanes(across);
  const __m128 origin_x = _mm_set1_ps(origin[0]);
  const __m128 origin_y = _mm_set1_ps(origin[1]);
  const __m128i nx = _mm_set1_epi32(along.n);
  for (; x + kFloatLanes <= width; x += kFloatLanes) {
    const __m128i in = _mm_cmpeq_epi32(load_lanes<__m128i>(cells + x), _mm_set1_epi32(kBinned));
    if (_mm_movemask_epi8(in) == 0)
      continue;
    const __m128 mask = _mm_castsi128_ps(in);
    const __m128 px =
        _mm_or_ps(_mm_and_ps(mask, _mm_loadu_ps(forward + x)), _mm_andnot_ps(mask, origin_x));
    const __m128 py =
        _mm_or_ps(_mm_and_ps(mask, _mm_loadu_ps(left + x)), _mm_andnot_ps(mask, origin_y));
    const __m128i index =
        _mm_add_epi32(multiply_lanes(across_lanes.cells_of(py), nx), along_lanes.cells_of(px));
    store_lanes(cells + x, _mm_or_si128(index, _mm_xor_si128(in, _mm_set1_epi32(-1))));
  }
#endif
  for (; x < width; ++x)
    if (cells[x] == kBinned)
      cells[x] = across.cell_of(left[x]) * along.n + along.cell_of(forward[x]);
}

// The cells' statistics, held in locals so that the stores to them are not read as stores to
// the grid's own members.
struct CellSums {
  float* highest;
  float* lowest;
  float* sum;
  std::int32_t* count;
};

std::uint64_t add_points(const std::int32_t* pixel_cell, const float* elevation, int width,
                         const CellSums& cells) {
  std::uint64_t points = 0;
  for (int x = 0; x < width; ++x) {
    if (pixel_cell[x] < 0)
      continue;
    const auto i = static_cast<std::size_t>(pixel_cell[x]);
    const float h = elevation[x];
    cells.highest[i] = std::max(cells.highest[i], h);
    cells.lowest[i] = std::min(cells.lowest[i], h);
    cells.sum[i] += h;
    ++cells.count[i];
    ++points;
  }
  return points;
}

} // namespace

GroundGrid::GroundGrid(const TerrainPoints& terrain, ImageView<const std::uint8_t> zone,
                       double cell_m, double max_range_m, std::pmr::memory_resource* memory,
                       std::uint64_t& work)
    : cell_(cell_m), width_(terrain.width()),
      pixel_cell_(static_cast<std::size_t>(terrain.width()) * terrain.height(), memory),
      highest_(memory), lowest_(memory), sum_(memory), count_(memory) {
  const Image<std::uint8_t> own =
      zone.channels() == 1 ? Image<std::uint8_t>(memory) : first_channel(zone, memory);
  const ImageView<const std::uint8_t> judged = zone.channels() == 1 ? zone : own.view();
  const auto max_range = static_cast<float>(max_range_m);
  for (int y = 0; y < terrain.height(); ++y)
    mark_binned(judged.row(y), terrain.elevation.row(y), terrain.range.row(y), max_range,
                terrain.width(), binned_row(y));
  const Bounds b = bounds_of(terrain, pixel_cell_.data());
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

void GroundGrid::bin(const TerrainPoints& terrain, const float (&origin)[2], std::uint64_t& work) {
  const auto size = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  highest_.assign(size, -kInfinity);
  lowest_.assign(size, kInfinity);
  sum_.assign(size, 0.0F);
  count_.assign(size, 0);
  const LatticeAxis along{x0_, cell_, nx_};
  const LatticeAxis across{y0_, cell_, ny_};
  const CellSums cells{highest_.data(), lowest_.data(), sum_.data(), count_.data()};
  std::uint64_t points = 0;
  for (int y = 0; y < terrain.height(); ++y) {
    std::int32_t* pixel_cell = binned_row(y);
    bin_row(terrain.forward.row(y), terrain.left.row(y), along, across, origin, terrain.width(),
            pixel_cell);
    points += add_points(pixel_cell, terrain.elevation.row(y), terrain.width(), cells);
  }
  work += 2 * points;
}

} // namespace marsokhod::nav::detail
