#include "zone_rules.hpp"

#include <utility>
#include <array>
#include <cmath>

namespace marsokhod::nav::detail {
namespace {

/// Known rows compared on each side, looked for among this many rows.
constexpr int kNeighbours = 4;
constexpr int kSearchRows = 8;

// Median ground distance of the first kNeighbours pixels of the column that are still judged,
// walking from row y in steps of `step` (-1 up the image, +1 down); NaN if there are none.
double neighbour_range(const TerrainPoints& terrain, const Image<std::uint8_t>& zone, int x,
                       int y, int step, std::uint64_t& tests) {
  std::array<double, kNeighbours> found{};
  int n = 0;
  for (int k = 1; k <= kSearchRows && n < kNeighbours; ++k) {
    const int row = y + step * k;
    if (row < 0 || row >= terrain.height())
      break;
    ++tests;
    if (zone(x, row) != static_cast<std::uint8_t>(Zone::unknown))
      found[static_cast<std::size_t>(n++)] = terrain.range(x, row);
  }
  if (n == 0)
    return std::nan("");
  // Insertion sort of at most kNeighbours values.
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && found[static_cast<std::size_t>(j)] < found[static_cast<std::size_t>(j - 1)]; --j)
      std::swap(found[static_cast<std::size_t>(j)], found[static_cast<std::size_t>(j - 1)]);
  return found[static_cast<std::size_t>(n / 2)];
}

} // namespace

std::uint64_t mark_out_of_order(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (options.order_tolerance <= 0.0)
    return 0;
  std::uint64_t tests = 0;
  const double slack = options.order_tolerance;
  Image<std::uint8_t> verdict(zone.width(), zone.height(), 1, 0, memory);
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x) {
      if (zone(x, y) == static_cast<std::uint8_t>(Zone::unknown))
        continue;
      const double own = terrain.range(x, y);
      const double above = neighbour_range(terrain, zone, x, y, -1, tests);
      const double below = neighbour_range(terrain, zone, x, y, +1, tests);
      // Seen from above, ground farther up the image is never nearer: a point beyond what the
      // rows above see, or nearer than what the rows below see, lies where no ray can reach.
      const bool too_far = !std::isnan(above) && own > above * (1.0 + slack) + kOrderSlack_m;
      const bool too_near = !std::isnan(below) && own < below * (1.0 - slack) - kOrderSlack_m;
      verdict(x, y) = too_far || too_near ? 1 : 0;
    }
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x)
      if (verdict(x, y) != 0)
        zone(x, y) = static_cast<std::uint8_t>(Zone::unknown);
  return tests;
}

} // namespace marsokhod::nav::detail
