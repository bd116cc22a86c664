// Zone rule: the rover's half-width of margin grown around steps and slopes.

#include "zones/zone_rules.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::nav::detail {
namespace {

// Only what was seen to be an obstacle is grown. Unknown ground is not traversable itself but
// gets no margin: the strip of the left view the right camera cannot see (x < d, a third of the
// near field at 256 px) and the sky would otherwise swallow the ground in front of the rover.
bool is_obstacle(std::uint8_t zone) {
  return zone == static_cast<std::uint8_t>(Zone::step) ||
         zone == static_cast<std::uint8_t>(Zone::slope);
}

// For each row dy of the disc (index dy + r), the largest dx with dx^2 + dy^2 <= reach^2, or -1
// when the row holds no cell; the test is the one a cell-by-cell stamp would make.
std::pmr::vector<int> disc_half_runs(int r, double reach, std::pmr::memory_resource* memory) {
  std::pmr::vector<int> half_run(static_cast<std::size_t>(2 * r + 1), -1, memory);
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = 0; dx <= r; ++dx)
      if (dx * dx + dy * dy <= reach * reach)
        half_run[static_cast<std::size_t>(dy + r)] = dx;
  return half_run;
}

// One row of flags grown by one cell either way.
void grow_row(const std::uint8_t* from, int n, std::uint8_t* to) {
  if (n == 1) {
    to[0] = from[0];
    return;
  }
  to[0] = from[0] | from[1];
  for (int i = 1; i + 1 < n; ++i)
    to[i] = from[i - 1] | from[i] | from[i + 1];
  to[n - 1] = from[n - 2] | from[n - 1];
}

// The flags grown by k = 1 .. widest cells along each row, one grid after another (grid k - 1
// from k): each from the one before, a pass of byte ORs that vectorises.
CellFlags spread_along_rows(const GroundGrid& grid, const CellFlags& flags, int widest,
                            std::pmr::memory_resource* memory) {
  const std::size_t cells = flags.size();
  CellFlags spread(cells * static_cast<std::size_t>(widest), memory);
  for (int k = 1; k <= widest; ++k) {
    const std::uint8_t* in = k == 1 ? flags.data() : spread.data() + (k - 2) * cells;
    std::uint8_t* out = spread.data() + (k - 1) * cells;
    for (int iy = 0; iy < grid.ny(); ++iy)
      grow_row(in + grid.index(0, iy), grid.nx(), out + grid.index(0, iy));
  }
  return spread;
}

} // namespace

CellFlags near_cells(const GroundGrid& grid, const CellFlags& obstacle, const ZoneOptions& options,
                     std::pmr::memory_resource* memory, RuleWork& tests) {
  CellFlags near(obstacle.size(), memory);
  std::fill_n(near.data(), near.size(), std::uint8_t{0});
  if (grid.empty() || options.rover_half_width_m <= 0.0)
    return near;
  std::uint64_t obstacles = 0;
  std::uint64_t own_obstacles = 0;
  for (int iy = 0; iy < grid.ny(); ++iy)
    for (int ix = 0; ix < grid.nx(); ++ix)
      if (obstacle[static_cast<std::size_t>(grid.index(ix, iy))] != 0) {
        ++obstacles;
        own_obstacles += grid.owns(ix) ? 1 : 0;
      }
  if (obstacles == 0)
    return near;
  // Every cell whose centre lies within the half-width of an obstacle cell's centre: the disc
  // of cells a stamp around each obstacle cell would cover, as the union over the disc's rows of
  // the obstacle flags grown along the rows by that row's half-run and moved across by its dy.
  const double reach = options.rover_half_width_m / grid.cell();
  const int r = margin_cells(grid.cell(), options);
  const std::pmr::vector<int> half_run = disc_half_runs(r, reach, memory);
  const auto disc = static_cast<std::uint64_t>(2 * r + 1) * static_cast<std::uint64_t>(2 * r + 1);
  tests.own += own_obstacles * disc;
  tests.halo += (obstacles - own_obstacles) * disc;
  // Growing by the whole row's width already reaches every cell of it.
  const int widest = std::min(r, grid.nx() - 1);
  const CellFlags spread = spread_along_rows(grid, obstacle, widest, memory);
  const auto grown = [&](int half) {
    const int k = std::min(half, widest);
    return k == 0 ? obstacle.data()
                  : spread.data() + static_cast<std::size_t>(k - 1) * obstacle.size();
  };
  // In a local, the row length is not reloaded after every store, and the loop vectorises.
  const int nx = grid.nx();
  for (int iy = 0; iy < grid.ny(); ++iy) {
    std::uint8_t* to = near.data() + grid.index(0, iy);
    for (int dy = std::max(-r, iy - (grid.ny() - 1)); dy <= std::min(r, iy); ++dy) {
      const int half = half_run[static_cast<std::size_t>(dy + r)];
      if (half < 0)
        continue;
      const std::uint8_t* from = grown(half) + grid.index(0, iy - dy);
      for (int ix = 0; ix < nx; ++ix)
        to[ix] |= from[ix];
    }
  }
  return near;
}

std::uint64_t grow_margin(const GroundGrid& grid, const ZoneOptions& options,
                          imaging::Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (grid.empty() || options.rover_half_width_m <= 0.0)
    return 0;
  const std::size_t cells = static_cast<std::size_t>(grid.nx()) * grid.ny();
  CellFlags obstacle(cells, memory);
  std::fill_n(obstacle.data(), cells, std::uint8_t{0});
  const std::ptrdiff_t channels = zone.channels();
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* pixel_cells = grid.cells_of_row(y);
    const std::uint8_t* row = zone.row(y);
    for (int x = 0; x < zone.width(); ++x)
      if (pixel_cells[x] >= 0 && is_obstacle(row[x * channels]))
        obstacle[static_cast<std::size_t>(pixel_cells[x])] = 1;
  }
  RuleWork tests;
  const CellFlags near = near_cells(grid, obstacle, options, memory, tests);
  mark_flagged_cells(grid, near, Zone::margin, zone);
  return tests.own;
}

} // namespace marsokhod::nav::detail
