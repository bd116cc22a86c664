// Tests: edge cases of the prohibited zones: exact range limits, masks, held-back pixels.

#include "nav/terrain_grid.hpp"

#include "marsokhod/nav/zones/zones.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

// Edges of find_zones' first passes: the range limit taken on floats, a mask of several
// channels, pixels held back for bridging, and the counts.

namespace marsokhod::nav {
namespace {

using testing::grid_terrain;
using testing::GridSpec;

ZoneOptions edge_grid_options() {
  ZoneOptions o;
  o.cell_m = 0.05;
  return o;
}

TEST(FindZonesEdges, RangeLimitBetweenTwoFloatsIsExact) {
  const GridSpec g;
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  const float r = t.range(10, 40);
  ZoneOptions options = edge_grid_options();
  // Just above the point's range, and no float lies between: the point is within range.
  options.max_range_m = std::nextafter(static_cast<double>(r), 1e9);
  EXPECT_NE(find_zones(t, {}, options).at(10, 40), Zone::unknown);
  // Just below: beyond range.
  options.max_range_m = std::nextafter(static_cast<double>(r), 0.0);
  EXPECT_EQ(find_zones(t, {}, options).at(10, 40), Zone::unknown);
}

TEST(FindZonesEdges, MaskOfSeveralChannelsReadsChannelZero) {
  const GridSpec g;
  const TerrainPoints t = grid_terrain(g, [](double x, double) { return x > 3.0 ? 0.5 : 0.0; });
  imaging::Image<std::uint8_t> single(g.width, g.height, 1, 255);
  imaging::Image<std::uint8_t> triple(g.width, g.height, 3, 255);
  for (int y = 20; y < 30; ++y)
    for (int x = 5; x < 40; x += 7) {
      single(x, y) = 0;
      triple(x, y, 0) = 0;
      triple(x + 1, y, 1) = 0; // other channels do not count
    }
  const ZoneMap a = find_zones(t, single, edge_grid_options());
  const ZoneMap b = find_zones(t, triple, edge_grid_options());
  EXPECT_EQ(a.zone, b.zone);
  EXPECT_EQ(a.counts, b.counts);
}

TEST(FindZonesEdges, HeldBackPixelsAreSettledAndCounted) {
  const GridSpec g;
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  imaging::Image<std::uint8_t> reliable(g.width, g.height, 1, 255);
  reliable(20, 30) = 0;       // a one-pixel gap: bridged
  for (int x = 0; x < 3; ++x) // a run at the row's start: no left end
    reliable(x, 31) = 0;
  for (int x = 10; x < 40; ++x) // a run far wider than a wheel
    reliable(x, 32) = 0;
  const ZoneMap zones = find_zones(t, reliable, edge_grid_options());
  EXPECT_EQ(zones.at(20, 30), Zone::traversable);
  EXPECT_EQ(zones.at(1, 31), Zone::unknown);
  EXPECT_EQ(zones.at(25, 32), Zone::unknown);
  std::array<std::uint64_t, kZoneKinds> counts{};
  for (int y = 0; y < zones.height(); ++y)
    for (int x = 0; x < zones.width(); ++x) {
      ASSERT_LT(zones.zone(x, y), kZoneKinds);
      ++counts[zones.zone(x, y)];
    }
  EXPECT_EQ(zones.counts, counts);
}

TEST(FindZonesEdges, UnreliablePixelWithoutRangeIsNotBridged) {
  const GridSpec g;
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  imaging::Image<std::uint8_t> reliable(g.width, g.height, 1, 255);
  reliable(20, 30) = 0;
  reliable(21, 30) = 0;
  t.range(21, 30) = std::numeric_limits<float>::quiet_NaN(); // not within range, so not bridged
  const ZoneMap zones = find_zones(t, reliable, edge_grid_options());
  EXPECT_EQ(zones.at(20, 30), Zone::unknown);
  EXPECT_EQ(zones.at(21, 30), Zone::unknown);
}

} // namespace
} // namespace marsokhod::nav
