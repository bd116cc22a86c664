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

// The bounds of the binned points and, in row-major order, the pixels that hold them (y *
// width + x), so that binning need not test every pixel again.
struct Binned {
  Bounds bounds;
  std::pmr::vector<std::int32_t> pixels;
};

Binned binned_pixels(const TerrainPoints& terrain, ImageView<const std::uint8_t> include,
                     double max_range, std::pmr::memory_resource* memory) {
  Binned out{Bounds{}, std::pmr::vector<std::int32_t>(memory)};
  Bounds& b = out.bounds;
  const int width = terrain.width();
  const std::ptrdiff_t channels = include.channels();
  out.pixels.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(terrain.height()));
  for (int y = 0; y < terrain.height(); ++y) {
    const float* forward = terrain.forward.row(y);
    const float* left = terrain.left.row(y);
    const float* elevation = terrain.elevation.row(y);
    const float* range = terrain.range.row(y);
    const std::uint8_t* included = include.row(y);
    for (int x = 0; x < width; ++x) {
      if (included[x * channels] == 0 || !std::isfinite(elevation[x]) || !(range[x] <= max_range))
        continue;
      b.min_x = std::min<double>(b.min_x, forward[x]);
      b.max_x = std::max<double>(b.max_x, forward[x]);
      b.min_y = std::min<double>(b.min_y, left[x]);
      b.max_y = std::max<double>(b.max_y, left[x]);
      out.pixels.push_back(y * width + x);
    }
  }
  return out;
}

} // namespace

GroundGrid::GroundGrid(const TerrainPoints& terrain, ImageView<const std::uint8_t> include,
                       double cell_m, double max_range_m, std::pmr::memory_resource* memory,
                       std::uint64_t& work)
    : cell_(cell_m), pixel_cell_(terrain.width(), terrain.height(), 1, -1, memory),
      highest_(memory), lowest_(memory), sum_(memory), count_(memory) {
  const Binned binned = binned_pixels(terrain, include, max_range_m, memory);
  const Bounds& b = binned.bounds;
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
  const float* forward = terrain.forward.data();
  const float* left = terrain.left.data();
  const float* elevation = terrain.elevation.data();
  std::int32_t* pixel_cell = pixel_cell_.data();
  for (const std::int32_t p : binned.pixels) {
    const auto at = static_cast<std::size_t>(p);
    const int ix =
        std::clamp(static_cast<int>(std::floor((forward[at] - x0_) / cell_)), 0, nx_ - 1);
    const int iy = std::clamp(static_cast<int>(std::floor((left[at] - y0_) / cell_)), 0, ny_ - 1);
    const auto i = static_cast<std::size_t>(index(ix, iy));
    const float h = elevation[at];
    highest_[i] = count_[i] == 0 ? h : std::max(highest_[i], h);
    lowest_[i] = count_[i] == 0 ? h : std::min(lowest_[i], h);
    sum_[i] += h;
    ++count_[i];
    pixel_cell[at] = static_cast<std::int32_t>(i);
  }
  work += 2 * binned.pixels.size();
}

} // namespace marsokhod::nav::detail
