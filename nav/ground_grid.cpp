#include "ground_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Bounds {
  float min_x = std::numeric_limits<float>::infinity();
  float max_x = -std::numeric_limits<float>::infinity();
  float min_y = std::numeric_limits<float>::infinity();
  float max_y = -std::numeric_limits<float>::infinity();
  bool empty() const { return min_x > max_x; }
};

// A pixel is binned when it is included, known and within range (NaN ranges fail the test).
bool binned(std::uint8_t included, float elevation, float range, float max_range) {
  return included != 0 && std::isfinite(elevation) && range <= max_range;
}

Bounds bounds_of(const TerrainPoints& terrain, ImageView<const std::uint8_t> include,
                 float max_range) {
  Bounds b;
  const std::ptrdiff_t channels = include.channels();
  for (int y = 0; y < terrain.height(); ++y) {
    const float* forward = terrain.forward.row(y);
    const float* left = terrain.left.row(y);
    const float* elevation = terrain.elevation.row(y);
    const float* range = terrain.range.row(y);
    const std::uint8_t* included = include.row(y);
    for (int x = 0; x < terrain.width(); ++x) {
      if (!binned(included[x * channels], elevation[x], range[x], max_range))
        continue;
      b.min_x = std::min(b.min_x, forward[x]);
      b.max_x = std::max(b.max_x, forward[x]);
      b.min_y = std::min(b.min_y, left[x]);
      b.max_y = std::max(b.max_y, left[x]);
    }
  }
  return b;
}

} // namespace

GroundGrid::GroundGrid(const TerrainPoints& terrain, ImageView<const std::uint8_t> include,
                       double cell_m, double max_range_m, std::pmr::memory_resource* memory,
                       std::uint64_t& work)
    : cell_(cell_m), pixel_cell_(terrain.width(), terrain.height(), 1, -1, memory),
      highest_(memory), lowest_(memory), sum_(memory), count_(memory) {
  const auto max_range = static_cast<float>(max_range_m);
  const Bounds b = bounds_of(terrain, include, max_range);
  if (b.empty())
    return;
  // The first point sits in the middle of its cell, so points on a regular lattice of the
  // cell's pitch fall into cells one to one.
  x0_ = b.min_x - 0.5 * cell_;
  y0_ = b.min_y - 0.5 * cell_;
  nx_ = static_cast<int>(std::floor((b.max_x - x0_) / cell_)) + 1;
  ny_ = static_cast<int>(std::floor((b.max_y - y0_) / cell_)) + 1;
  const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  highest_.assign(cells, -kInfinity);
  lowest_.assign(cells, kInfinity);
  sum_.assign(cells, 0.0F);
  count_.assign(cells, 0);
  const std::ptrdiff_t channels = include.channels();
  std::uint64_t points = 0;
  for (int y = 0; y < terrain.height(); ++y) {
    const float* forward = terrain.forward.row(y);
    const float* left = terrain.left.row(y);
    const float* elevation = terrain.elevation.row(y);
    const float* range = terrain.range.row(y);
    const std::uint8_t* included = include.row(y);
    std::int32_t* pixel_cell = pixel_cell_.row(y);
    for (int x = 0; x < terrain.width(); ++x) {
      if (!binned(included[x * channels], elevation[x], range[x], max_range))
        continue;
      // Offsets are never negative beyond rounding: truncation is the floor once clamped.
      const int ix = std::clamp(static_cast<int>((forward[x] - x0_) / cell_), 0, nx_ - 1);
      const int iy = std::clamp(static_cast<int>((left[x] - y0_) / cell_), 0, ny_ - 1);
      const auto i = static_cast<std::size_t>(index(ix, iy));
      const float h = elevation[x];
      highest_[i] = std::max(highest_[i], h);
      lowest_[i] = std::min(lowest_[i], h);
      sum_[i] += h;
      ++count_[i];
      pixel_cell[x] = static_cast<std::int32_t>(i);
      ++points;
    }
  }
  work += 2 * points;
}

} // namespace marsokhod::nav::detail
