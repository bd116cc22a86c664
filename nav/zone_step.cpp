#include "sliding_extremes.hpp"
#include "zone_rules.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::nav::detail {
namespace {

struct Extremes {
  std::pmr::vector<float> highest;
  std::pmr::vector<float> lowest;
};

// Window [i - r, i + r] clipped to 0..n-1, as the bounds sliding_max/min take.
void fill_window(int n, int r, std::pmr::vector<int>& first, std::pmr::vector<int>& last) {
  first.resize(static_cast<std::size_t>(n));
  last.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    first[static_cast<std::size_t>(i)] = std::max(0, i - r);
    last[static_cast<std::size_t>(i)] = std::min(n - 1, i + r);
  }
}

// The extremes over the square window of +-r cells, separably: along x, then along y.
Extremes window_extremes(const GroundGrid& grid, int r, std::pmr::memory_resource* memory,
                         std::uint64_t& comparisons) {
  const int nx = grid.nx();
  const int ny = grid.ny();
  const std::size_t cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  Extremes along_x{std::pmr::vector<float>(cells, memory), std::pmr::vector<float>(cells, memory)};
  Extremes out{std::pmr::vector<float>(cells, memory), std::pmr::vector<float>(cells, memory)};
  std::pmr::vector<int> first(memory);
  std::pmr::vector<int> last(memory);
  std::pmr::vector<int> deque(static_cast<std::size_t>(std::max(nx, ny)), memory);
  fill_window(nx, r, first, last);
  for (int iy = 0; iy < ny; ++iy) {
    const std::size_t row = static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx);
    comparisons += sliding_max({grid.highest().data() + row, 1}, nx, first.data(), last.data(),
                               {along_x.highest.data() + row, 1}, deque.data());
    comparisons += sliding_min({grid.lowest().data() + row, 1}, nx, first.data(), last.data(),
                               {along_x.lowest.data() + row, 1}, deque.data());
  }
  fill_window(ny, r, first, last);
  for (int ix = 0; ix < nx; ++ix) {
    comparisons += sliding_max({along_x.highest.data() + ix, nx}, ny, first.data(), last.data(),
                               {out.highest.data() + ix, nx}, deque.data());
    comparisons += sliding_min({along_x.lowest.data() + ix, nx}, ny, first.data(), last.data(),
                               {out.lowest.data() + ix, nx}, deque.data());
  }
  return out;
}

} // namespace

int cells_within(const GroundGrid& grid, double distance_m) {
  return std::max(1, static_cast<int>(std::lround(distance_m / grid.cell())));
}

int cells_apart_within(const GroundGrid& grid, double distance_m) {
  // The relative nudge keeps 0.30 / 0.10 at 3 despite rounding.
  const double cells = std::floor(distance_m / grid.cell() * (1.0 + 1e-9));
  return std::max(1, static_cast<int>(cells) - 1);
}

std::uint64_t mark_steps(const GroundGrid& grid, const TerrainPoints& terrain,
                         const ZoneOptions& options, Image<std::uint8_t>& zone,
                         std::pmr::memory_resource* memory) {
  if (grid.empty())
    return 0;
  std::uint64_t comparisons = 0;
  const Extremes window =
      window_extremes(grid, cells_apart_within(grid, options.step_baseline_m), memory, comparisons);
  const auto limit = static_cast<float>(options.max_step_m);
  const auto traversable = static_cast<std::uint8_t>(Zone::traversable);
  const std::ptrdiff_t channels = zone.channels();
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* cells = grid.cells_of_row(y);
    const float* elevation = terrain.elevation.row(y);
    std::uint8_t* row = zone.row(y);
    for (int x = 0; x < zone.width(); ++x) {
      std::uint8_t& pixel = row[x * channels];
      if (cells[x] < 0 || pixel != traversable)
        continue;
      // Some point of the window is higher, or lower, than this one by more than the limit
      // (an empty window holds -inf and +inf, which the tests below reject).
      const float own = elevation[x];
      const auto i = static_cast<std::size_t>(cells[x]);
      comparisons += 2;
      if ((window.highest[i] - own > limit) || (own - window.lowest[i] > limit))
        pixel = static_cast<std::uint8_t>(Zone::step);
    }
  }
  return comparisons;
}

} // namespace marsokhod::nav::detail
