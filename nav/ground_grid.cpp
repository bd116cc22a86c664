#include "ground_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Bounds {
  double min_x = std::numeric_limits<double>::infinity();
  double max_x = -std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity();
  double max_y = -std::numeric_limits<double>::infinity();
  bool empty() const { return min_x > max_x; }
};

bool binned(const TerrainPoints& terrain, ImageView<const std::uint8_t> include, double max_range,
            int x, int y) {
  return include(x, y) != 0 && terrain.known(x, y) && terrain.range(x, y) <= max_range;
}

Bounds bounds_of(const TerrainPoints& terrain, ImageView<const std::uint8_t> include,
                 double max_range) {
  Bounds b;
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width(); ++x)
      if (binned(terrain, include, max_range, x, y)) {
        b.min_x = std::min<double>(b.min_x, terrain.forward(x, y));
        b.max_x = std::max<double>(b.max_x, terrain.forward(x, y));
        b.min_y = std::min<double>(b.min_y, terrain.left(x, y));
        b.max_y = std::max<double>(b.max_y, terrain.left(x, y));
      }
  return b;
}

} // namespace

GroundGrid::GroundGrid(const TerrainPoints& terrain, ImageView<const std::uint8_t> include,
                       double cell_m, double max_range_m, std::pmr::memory_resource* memory,
                       std::uint64_t& work)
    : cell_(cell_m), pixel_cell_(terrain.width(), terrain.height(), 1, -1, memory),
      highest_(memory), lowest_(memory), sum_(memory), count_(memory) {
  const Bounds b = bounds_of(terrain, include, max_range_m);
  if (b.empty())
    return;
  // The first point sits in the middle of its cell, so points on a regular lattice of the
  // cell's pitch fall into cells one to one.
  x0_ = b.min_x - 0.5 * cell_;
  y0_ = b.min_y - 0.5 * cell_;
  nx_ = static_cast<int>(std::floor((b.max_x - x0_) / cell_)) + 1;
  ny_ = static_cast<int>(std::floor((b.max_y - y0_) / cell_)) + 1;
  const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  highest_.assign(cells, kInfinity);
  lowest_.assign(cells, kInfinity);
  sum_.assign(cells, 0.0F);
  count_.assign(cells, 0);
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width(); ++x) {
      if (!binned(terrain, include, max_range_m, x, y))
        continue;
      const int ix = std::clamp(static_cast<int>(std::floor((terrain.forward(x, y) - x0_) / cell_)), 0, nx_ - 1);
      const int iy = std::clamp(static_cast<int>(std::floor((terrain.left(x, y) - y0_) / cell_)), 0, ny_ - 1);
      const auto i = static_cast<std::size_t>(index(ix, iy));
      const float h = terrain.elevation(x, y);
      highest_[i] = count_[i] == 0 ? h : std::max(highest_[i], h);
      lowest_[i] = count_[i] == 0 ? h : std::min(lowest_[i], h);
      sum_[i] += h;
      ++count_[i];
      pixel_cell_(x, y) = static_cast<std::int32_t>(i);
      work += 2;
    }
}

} // namespace marsokhod::nav::detail
