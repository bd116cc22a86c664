// Zone counts: how many pixels of a zone map fall into each zone, sixteen at a time.

#include "zones/zone_rules.hpp"

#include <bit>
#include <cstring>

namespace marsokhod::nav::detail {
namespace {

using Bytes16 = std::uint8_t __attribute__((vector_size(16)));
using Counters = std::array<std::uint64_t, kZoneKinds>;
constexpr int kLaneBytes = 16;
// A byte lane counts up to 255 before it is folded into the totals.
constexpr int kChunksPerFold = 255;

// Counts of the values 0 .. kZoneKinds - 2 among `n` single-channel pixels, sixteen at a
// time: a match is -1 in its byte lane, so subtracting it counts it.
void count_run(const std::uint8_t* pixels, int n, Counters& counts) {
  int x = 0;
  while (x + kLaneBytes <= n) {
    Bytes16 lanes[kZoneKinds - 1] = {};
    for (int chunk = 0; chunk < kChunksPerFold && x + kLaneBytes <= n; ++chunk, x += kLaneBytes) {
      Bytes16 v;
      std::memcpy(&v, pixels + x, sizeof v);
      for (int k = 0; k < kZoneKinds - 1; ++k)
        lanes[k] -= std::bit_cast<Bytes16>(v == static_cast<std::uint8_t>(k));
    }
    for (int k = 0; k < kZoneKinds - 1; ++k)
      for (int lane = 0; lane < kLaneBytes; ++lane)
        counts[static_cast<std::size_t>(k)] += lanes[k][lane];
  }
  for (; x < n; ++x)
    if (pixels[x] < kZoneKinds - 1)
      ++counts[pixels[x]];
}

} // namespace

Counters count_zones(const imaging::Image<std::uint8_t>& zone) {
  Counters counts{};
  for (int y = 0; y < zone.height(); ++y) {
    if (zone.channels() == 1) {
      count_run(zone.row(y), zone.width(), counts);
      continue;
    }
    for (int x = 0; x < zone.width(); ++x)
      if (zone(x, y) < kZoneKinds - 1)
        ++counts[zone(x, y)];
  }
  // Every other value counts as the last zone.
  std::uint64_t others = static_cast<std::uint64_t>(zone.width()) * zone.height();
  for (int k = 0; k < kZoneKinds - 1; ++k)
    others -= counts[static_cast<std::size_t>(k)];
  counts[kZoneKinds - 1] = others;
  return counts;
}

} // namespace marsokhod::nav::detail
