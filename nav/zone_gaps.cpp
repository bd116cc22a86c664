#include "zone_rules.hpp"

#include <cmath>

namespace marsokhod::nav::detail {
namespace {

constexpr auto kUnknown = static_cast<std::uint8_t>(Zone::unknown);
constexpr auto kTraversable = static_cast<std::uint8_t>(Zone::traversable);

// Unknown only because the left-right check failed there: the fill gave it a point in range.
bool bridgeable(const TerrainPoints& terrain, const ZoneOptions& options,
                const Image<std::uint8_t>& zone, int x, int y) {
  return zone(x, y) == kUnknown && terrain.known(x, y) &&
         terrain.range(x, y) <= options.max_range_m;
}

// The ends of a gap are close on the ground and at about the same height.
bool narrow_and_level(const TerrainPoints& terrain, const ZoneOptions& options, int y, int left,
                      int right) {
  const double gap = std::hypot(terrain.forward(right, y) - terrain.forward(left, y),
                                terrain.left(right, y) - terrain.left(left, y));
  const double rise = std::abs(terrain.elevation(right, y) - terrain.elevation(left, y));
  return gap < options.bridged_gap_m && rise <= options.max_step_m;
}

} // namespace

std::uint64_t bridge_small_gaps(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone) {
  if (options.bridged_gap_m <= 0.0)
    return 0;
  std::uint64_t tests = 0;
  for (int y = 0; y < zone.height(); ++y) {
    int x = 0;
    while (x < zone.width()) {
      if (!bridgeable(terrain, options, zone, x, y)) {
        ++x;
        continue;
      }
      const int first = x;
      while (x < zone.width() && bridgeable(terrain, options, zone, x, y))
        ++x;
      // [first, x) is the run; its ends must be seen ground on both sides.
      if (first == 0 || x == zone.width() || zone(first - 1, y) != kTraversable ||
          zone(x, y) != kTraversable)
        continue;
      ++tests;
      if (!narrow_and_level(terrain, options, y, first - 1, x))
        continue;
      for (int i = first; i < x; ++i)
        zone(i, y) = kTraversable;
    }
  }
  return tests;
}

} // namespace marsokhod::nav::detail
