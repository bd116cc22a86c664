#include "zone_rules.hpp"

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

} // namespace

std::uint64_t grow_margin(const GroundGrid& grid, const ZoneOptions& options,
                          Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (grid.empty() || options.rover_half_width_m <= 0.0)
    return 0;
  std::uint64_t tests = 0;
  const std::size_t cells = static_cast<std::size_t>(grid.nx()) * grid.ny();
  std::pmr::vector<std::uint8_t> obstacle(cells, 0, memory);
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x) {
      const int cell = grid.cell_of(x, y);
      if (cell >= 0 && is_obstacle(zone(x, y)))
        obstacle[static_cast<std::size_t>(cell)] = 1;
    }
  // Every cell whose centre lies within the half-width of an obstacle cell's centre: a disc of
  // cells stamped around each obstacle cell.
  const double reach = options.rover_half_width_m / grid.cell();
  const int r = static_cast<int>(std::floor(reach));
  std::pmr::vector<std::uint8_t> near(cells, 0, memory);
  for (int iy = 0; iy < grid.ny(); ++iy)
    for (int ix = 0; ix < grid.nx(); ++ix) {
      if (obstacle[static_cast<std::size_t>(grid.index(ix, iy))] == 0)
        continue;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          ++tests;
          if (dx * dx + dy * dy <= reach * reach && grid.inside(ix + dx, iy + dy))
            near[static_cast<std::size_t>(grid.index(ix + dx, iy + dy))] = 1;
        }
    }
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x) {
      const int cell = grid.cell_of(x, y);
      if (cell >= 0 && near[static_cast<std::size_t>(cell)] != 0 &&
          zone(x, y) == static_cast<std::uint8_t>(Zone::traversable))
        zone(x, y) = static_cast<std::uint8_t>(Zone::margin);
    }
  return tests;
}

} // namespace marsokhod::nav::detail
