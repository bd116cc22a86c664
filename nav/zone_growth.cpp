#include "zone_rules.hpp"

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

void stamp_disc(const GroundGrid& grid, int ix, int iy, const std::pmr::vector<int>& half_run,
                std::pmr::vector<std::uint8_t>& near) {
  const int r = static_cast<int>(half_run.size() / 2);
  for (int dy = std::max(-r, -iy); dy <= std::min(r, grid.ny() - 1 - iy); ++dy) {
    const int half = half_run[static_cast<std::size_t>(dy + r)];
    if (half < 0)
      continue;
    const int first = std::max(0, ix - half);
    const int last = std::min(grid.nx() - 1, ix + half);
    if (first > last)
      continue;
    const auto row = near.begin() + grid.index(first, iy + dy);
    std::fill(row, row + (last - first + 1), std::uint8_t{1});
  }
}

} // namespace

std::uint64_t grow_margin(const GroundGrid& grid, const ZoneOptions& options,
                          Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (grid.empty() || options.rover_half_width_m <= 0.0)
    return 0;
  std::uint64_t tests = 0;
  const std::size_t cells = static_cast<std::size_t>(grid.nx()) * grid.ny();
  std::pmr::vector<std::uint8_t> obstacle(cells, 0, memory);
  const std::ptrdiff_t channels = zone.channels();
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* pixel_cells = grid.cells_of_row(y);
    const std::uint8_t* row = zone.row(y);
    for (int x = 0; x < zone.width(); ++x)
      if (pixel_cells[x] >= 0 && is_obstacle(row[x * channels]))
        obstacle[static_cast<std::size_t>(pixel_cells[x])] = 1;
  }
  // Every cell whose centre lies within the half-width of an obstacle cell's centre: a disc of
  // cells stamped around each obstacle cell, one run of cells per row of the disc.
  const double reach = options.rover_half_width_m / grid.cell();
  const int r = static_cast<int>(std::floor(reach));
  const std::pmr::vector<int> half_run = disc_half_runs(r, reach, memory);
  const auto disc_tests =
      static_cast<std::uint64_t>(2 * r + 1) * static_cast<std::uint64_t>(2 * r + 1);
  std::pmr::vector<std::uint8_t> near(cells, 0, memory);
  for (int iy = 0; iy < grid.ny(); ++iy)
    for (int ix = 0; ix < grid.nx(); ++ix) {
      if (obstacle[static_cast<std::size_t>(grid.index(ix, iy))] == 0)
        continue;
      tests += disc_tests;
      stamp_disc(grid, ix, iy, half_run, near);
    }
  mark_flagged_cells(grid, near, Zone::margin, zone);
  return tests;
}

} // namespace marsokhod::nav::detail
