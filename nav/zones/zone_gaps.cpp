// Zone rule: short, level gaps of unreliable pixels along a row bridged as traversable.

#include "zones/zone_bytes.hpp"
#include "zones/zone_rules.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace marsokhod::nav::detail {
namespace {

// The ends of a gap are close on the ground and at about the same height.
bool narrow_and_level(const TerrainRows::Row& points, const ZoneOptions& options, int left,
                      int right) {
  const double gap = std::hypot(points.forward[right] - points.forward[left],
                                points.left[right] - points.left[left]);
  const double rise = std::abs(points.elevation[right] - points.elevation[left]);
  return gap < options.bridged_gap_m && rise <= options.max_step_m;
}

// The verdict on the run [first, end) of held-back pixels of row y.
std::uint8_t run_verdict(const TerrainRows& terrain, const ZoneOptions& options,
                         const std::uint8_t* row, int y, int first, int end, std::uint64_t& tests) {
  const int width = terrain.width();
  // The run's ends must be seen ground on both sides.
  if (options.bridged_gap_m <= 0.0 || first == 0 || end == width ||
      row[first - 1] != kTraversableZone || row[end] != kTraversableZone)
    return kUnknownZone;
  ++tests;
  return narrow_and_level(terrain.row(y), options, first - 1, end) ? kTraversableZone
                                                                   : kUnknownZone;
}

} // namespace

std::uint64_t bridge_small_gaps(const TerrainRows& terrain, const ZoneOptions& options,
                                imaging::Image<std::uint8_t>& zone) {
  std::uint64_t tests = 0;
  const int width = zone.width();
  for (int y = 0; y < zone.height(); ++y) {
    std::uint8_t* row = zone.row(y);
    int x = 0;
    // Held-back pixels are few: the library's byte search skips to the next one.
    while (const void* hit =
               std::memchr(row + x, kUnreliable, static_cast<std::size_t>(width - x))) {
      const auto first = static_cast<int>(static_cast<const std::uint8_t*>(hit) - row);
      x = first;
      while (x < width && row[x] == kUnreliable)
        ++x;
      std::fill(row + first, row + x, run_verdict(terrain, options, row, y, first, x, tests));
    }
  }
  return tests;
}

} // namespace marsokhod::nav::detail
