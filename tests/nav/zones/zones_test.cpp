// Tests: the prohibited zones (steps, slopes, margins, unknown ground) on hand-made terrain.

#include "nav/terrain_grid.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav/zones/zones.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>

// Most tests use the map-like grid of terrain_grid.hpp with 5 cm pixels and rules on a 5 cm
// ground grid, so that each pixel has its own cell and distances are whole pixels: baselines
// of 0.32 m and 0.64 m reach 6 cells each way, the 0.52 m half-width a disc of radius 10.4.

namespace marsokhod::nav {
namespace {

using testing::grid_terrain;
using testing::GridSpec;

using test_support::kInf;

ZoneOptions grid_options() {
  ZoneOptions o;
  o.step_baseline_m = 0.32;
  o.slope_baseline_m = 0.64;
  o.rover_half_width_m = 0.52;
  o.cell_m = 0.05;
  return o;
}

struct Box {
  int x0, y0, x1, y1; // inclusive
  double height;
};

TerrainPoints grid_with_box(const GridSpec& g, const Box& box) {
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x)
      t.elevation(x, y) = static_cast<float>(box.height);
  return t;
}

// Chebyshev distance from a pixel to the box (0 inside).
int distance_to_box(const Box& b, int x, int y) {
  const int dx = std::max({b.x0 - x, 0, x - b.x1});
  const int dy = std::max({b.y0 - y, 0, y - b.y1});
  return std::max(dx, dy);
}

// Squared Euclidean distance, in pixels, from a pixel to the box grown by `grow` each way.
int squared_distance_to_grown_box(const Box& b, int grow, int x, int y) {
  const int dx = std::max({b.x0 - grow - x, 0, x - b.x1 - grow});
  const int dy = std::max({b.y0 - grow - y, 0, y - b.y1 - grow});
  return dx * dx + dy * dy;
}

TEST(FindZones, FlatGroundIsTraversableEverywhere) {
  const TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.1; });
  const ZoneMap zones = find_zones(t, {}, grid_options());
  EXPECT_EQ(zones.count(Zone::traversable), 64U * 64U);
}

TEST(FindZones, StepOverTheLimitProhibitsTheBoxAndABaselineAroundItThenTheMargin) {
  const GridSpec g;
  const Box box{25, 25, 34, 34, 0.35};
  const ZoneMap zones = find_zones(grid_with_box(g, box), {}, grid_options());
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      // Step within 5 cells (0.25 m, the farthest pair of 0.05 m cells within the 0.32 m
      // baseline) of the box; margin within 10.4 cells of a step cell.
      const int distance = distance_to_box(box, x, y);
      const Zone expected = distance <= 5 ? Zone::step
                            : squared_distance_to_grown_box(box, 5, x, y) <= 108
                                ? Zone::margin
                                : Zone::traversable;
      ASSERT_EQ(zones.at(x, y), expected) << x << "," << y << " at distance " << distance;
    }
}

TEST(FindZones, AStepUnderTheLimitIsPassable) {
  // 0.25 m: under the 0.30 m step, and 0.25 / 0.60 m = 22.6 deg at most under the 25 deg slope.
  const ZoneMap zones =
      find_zones(grid_with_box(GridSpec{}, {25, 25, 34, 34, 0.25}), {}, grid_options());
  EXPECT_EQ(zones.count(Zone::traversable), 64U * 64U);
}

TEST(FindZones, TheStepLimitIsConfigurable) {
  ZoneOptions options = grid_options();
  options.max_step_m = 0.20;
  const ZoneMap zones = find_zones(grid_with_box(GridSpec{}, {25, 25, 34, 34, 0.25}), {}, options);
  EXPECT_EQ(zones.at(30, 30), Zone::step);
  EXPECT_EQ(zones.at(30, 25 - 5), Zone::step);
  EXPECT_EQ(zones.at(30, 25 - 6), Zone::margin);
}

TEST(FindZones, SlopesSteeperThanTheLimitAreProhibited) {
  for (const double degrees : {20.0, 24.0, 26.0, 30.0}) {
    const double rise = std::tan(degrees * std::numbers::pi / 180.0);
    // Rising away from the rover and to the left at once: the gradient's size is what counts.
    const TerrainPoints t = grid_terrain(GridSpec{}, [&](double forward, double left) {
      return rise * (0.6 * forward + 0.8 * left);
    });
    const ZoneMap zones = find_zones(t, {}, grid_options());
    // The grid's edge is unseen ground: within the 0.32 m half-baseline (6 cells) of it only
    // the other axis is measured, whose share of the gradient, 0.8 tan(30 deg) = 0.46 at most,
    // stays under tan(25 deg) = 0.466. Those cells lie within the margin of the 52 x 52 steep
    // ones.
    const bool steep = degrees > 25.0;
    EXPECT_EQ(zones.count(Zone::slope), steep ? 52U * 52U : 0U) << degrees;
    EXPECT_EQ(zones.count(Zone::margin), steep ? 64U * 64U - 52U * 52U : 0U) << degrees;
    EXPECT_EQ(zones.count(Zone::traversable), steep ? 0U : 64U * 64U) << degrees;
  }
}

TEST(FindZones, ALowRockAtTheNearEdgeOfWhatWasSeenIsNoSlope) {
  // The 0.20 m block of the test below, cut by the bottom rows of the view (the nearest ground
  // seen): its flank reads atan(0.20 / 0.64) = 17 deg over the baseline, but measured against
  // the grid's edge, over half the baseline, it would read atan(0.20 / 0.32) = 32 deg, and the
  // ground in front of the rover would be its margin.
  const Box box{28, 56, 35, 63, 0.20};
  const ZoneMap zones = find_zones(grid_with_box(GridSpec{}, box), {}, grid_options());
  EXPECT_EQ(zones.count(Zone::slope), 0U);
  EXPECT_EQ(zones.count(Zone::step), 0U);
  EXPECT_EQ(zones.count(Zone::traversable), 64U * 64U);
}

TEST(FindZones, ALowRockWithHiddenGroundBehindItIsNoSlope) {
  // A 0.20 m block (under the step limit; over the 0.64 m slope baseline its flank reads
  // atan(0.20 / 0.64) = 17 deg) with the ground behind it hidden, as a rock hides it from the
  // mast: 10 rows beyond the block unknown across the block and 8 columns either side. The
  // block's top sees ground 0.32 m in front of it and nothing 0.32 m behind it; measured
  // one-sided over half the baseline it would read atan(0.20 / 0.32) = 32 deg.
  const GridSpec g;
  const Box box{28, 30, 35, 37, 0.20};
  TerrainPoints t = grid_with_box(g, box);
  for (int y = box.y0 - 10; y < box.y0; ++y)
    for (int x = box.x0 - 8; x <= box.x1 + 8; ++x)
      t.elevation(x, y) = t.forward(x, y) = t.left(x, y) = t.range(x, y) = kInf;
  const ZoneMap zones = find_zones(t, {}, grid_options());
  EXPECT_EQ(zones.count(Zone::slope), 0U);
  EXPECT_EQ(zones.count(Zone::step), 0U);
  EXPECT_EQ(zones.count(Zone::unknown), 10U * (box.x1 - box.x0 + 17));
  EXPECT_EQ(zones.count(Zone::traversable), 64U * 64U - zones.count(Zone::unknown));
}

TEST(FindZones, ASidePairOfSamplesAloneMeasuresNoSlope) {
  // Level ground with one cell raised 0.29 m (under the step limit), as points smeared across an
  // occluding edge raise it, diagonally 6 cells (the half-baseline) from cell (32, 32). Two cells
  // of that cell's own line and of its other side line along x are unseen, so along x only the
  // side pair through the raised cell is seen: alone it would read 0.29 / 0.60 m, 25.8 deg.
  // Every other cell pairs the raised one with level ones, 0.29 / 2 / 0.60 m (13.6 deg) at most.
  TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  t.elevation(26, 26) = 0.29F;
  for (const int y : {32, 38})
    t.elevation(26, y) = t.forward(26, y) = t.left(26, y) = t.range(26, y) = kInf;
  const ZoneMap zones = find_zones(t, {}, grid_options());
  EXPECT_EQ(zones.count(Zone::slope), 0U);
  EXPECT_EQ(zones.count(Zone::step), 0U);
  EXPECT_EQ(zones.count(Zone::unknown), 2U);
  EXPECT_EQ(zones.count(Zone::traversable), 64U * 64U - 2U);
}

TEST(FindZones, UnknownGroundIsNotTraversableButGetsNoMargin) {
  TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  t.elevation(30, 30) = t.forward(30, 30) = t.left(30, 30) = t.range(30, 30) = kInf;
  const ZoneMap zones = find_zones(t, {}, grid_options());
  EXPECT_EQ(zones.at(30, 30), Zone::unknown);
  EXPECT_EQ(zones.count(Zone::unknown), 1U);
  EXPECT_EQ(zones.count(Zone::traversable), 64U * 64U - 1U);
}

TEST(FindZones, UnreliablePixelsAreUnknownOnlyWhenAsked) {
  const TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  imaging::Image<std::uint8_t> reliable(64, 64, 1, 255);
  reliable(10, 50) = 0;
  ZoneOptions options = grid_options();
  options.bridged_gap_m = 0.0; // a one-pixel gap on level ground would be bridged
  options.unreliable_is_unknown = false;
  EXPECT_EQ(find_zones(t, reliable, options).at(10, 50), Zone::traversable);
  options.unreliable_is_unknown = true;
  EXPECT_EQ(find_zones(t, reliable, options).at(10, 50), Zone::unknown);
}

TEST(AddMargin, IsTheRoverHalfWidthOnTheGroundWhateverThePerspective) {
  // The paper's rig at 256 px looking at level ground (d = (B / h) (f sin a + y cos a)), with
  // one step pixel near and one far: the margin is every pixel whose ground point lies within
  // the half-width of a step's, up to the 10 cm cells' quantisation (a cell diagonal, 0.15 m).
  const imaging::StereoRig rig{imaging::RigParameters{}};
  imaging::Image<float> disparity(256, 256, 1, kInf);
  const double a = 10.0 * std::numbers::pi / 180.0;
  for (int v = 0; v < 256; ++v) {
    const double d = 0.5 * (rig.focal_px() * std::sin(a) + (v - rig.cy()) * std::cos(a));
    for (int u = 0; u < 256; ++u)
      if (d > 0.0)
        disparity(u, v) = static_cast<float>(d);
  }
  const TerrainPoints t = reconstruct_terrain(disparity, rig, {});
  ZoneMap zones{imaging::Image<std::uint8_t>(256, 256, 1, 0), {}};
  struct Pixel {
    int x, y;
  };
  const Pixel steps[] = {{128, 230}, {128, 100}};
  for (const Pixel& p : steps)
    zones.zone(p.x, p.y) = static_cast<std::uint8_t>(Zone::step);
  ZoneOptions options;
  options.rover_half_width_m = 0.5;
  add_margin(t, options, zones);
  int near_row_width = 0;
  int far_row_width = 0;
  for (int y = 60; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      double nearest = kInf;
      for (const Pixel& p : steps)
        nearest = std::min<double>(nearest, std::hypot(t.forward(x, y) - t.forward(p.x, p.y),
                                                       t.left(x, y) - t.left(p.x, p.y)));
      if (zones.at(x, y) == Zone::step)
        continue;
      // Well inside the half-width: margin; well outside it: traversable.
      const Zone expected = nearest < 0.5 - 0.15   ? Zone::margin
                            : nearest > 0.5 + 0.15 ? Zone::traversable
                                                   : zones.at(x, y);
      ASSERT_EQ(zones.at(x, y), expected) << x << "," << y;
      near_row_width += (y == 230 && zones.at(x, y) == Zone::margin) ? 1 : 0;
      far_row_width += (y == 100 && zones.at(x, y) == Zone::margin) ? 1 : 0;
    }
  // A metre across is some 170 columns at 2.4 m and some 50 at 8.3 m.
  EXPECT_GT(near_row_width, 3 * far_row_width);
  EXPECT_EQ(zones.count(Zone::step), 2U);
}

TEST(FindZones, PixelsThatSeeBeyondTheRowsAboveThemAreUnknown) {
  // A stereo mismatch: one pixel of a column sees 3 m farther than the rows above it, which
  // level ground seen from above cannot do.
  TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  t.forward(20, 50) += 3.0F;
  t.range(20, 50) = std::hypot(t.forward(20, 50), t.left(20, 50));
  ZoneOptions options = grid_options();
  EXPECT_EQ(find_zones(t, {}, options).at(20, 50), Zone::unknown);
  EXPECT_EQ(find_zones(t, {}, options).count(Zone::unknown), 1U);
  options.order_tolerance = 0.0;
  EXPECT_EQ(find_zones(t, {}, options).count(Zone::unknown), 0U);
}

TEST(FindZones, AClusterOfMismatchesAtTheFootOfAColumnIsOutvotedByTheRest) {
  // The bottom 8 pixels of column 20 (really 2.0-2.35 m ahead) all see 4.5 m: a rock whose
  // disparity lay outside the search, matched as one piece to the wrong place. Each agrees with
  // its neighbours; only the column as a whole shows that ground farther up the image is nearer.
  const GridSpec g;
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  for (int y = g.height - 8; y < g.height; ++y) {
    t.forward(20, y) = 4.5F;
    t.range(20, y) = std::hypot(t.forward(20, y), t.left(20, y));
  }
  const ZoneMap zones = find_zones(t, {}, grid_options());
  EXPECT_EQ(zones.count(Zone::unknown), 8U);
  for (int y = g.height - 8; y < g.height; ++y)
    EXPECT_EQ(zones.at(20, y), Zone::unknown) << y;
}

TEST(FindZones, RangeNoiseWithinTheOrderToleranceKeepsEveryPixel) {
  // Ranges jittered by up to 2 %: the rows of a column no longer increase strictly, but no
  // pixel contradicts the column by more than the 5 % tolerance.
  const GridSpec g;
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  std::uint32_t state = 7;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      state = state * 1664525U + 1013904223U;
      const double jitter = 0.02 * (static_cast<double>(state >> 8) / double(1 << 24) * 2.0 - 1.0);
      t.range(x, y) *= static_cast<float>(1.0 + jitter);
    }
  EXPECT_EQ(find_zones(t, {}, grid_options()).count(Zone::unknown), 0U);
}

TEST(FindZones, ReportsFewerHazardTestsForLessKnownGround) {
  const GridSpec g;
  const TerrainPoints full = grid_terrain(g, [](double, double) { return 0.0; });
  TerrainPoints half = full;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width / 2; ++x)
      half.elevation(x, y) = kInf;
  CountingMeter full_meter;
  CountingMeter half_meter;
  find_zones(full, {}, grid_options(), full_meter);
  find_zones(half, {}, grid_options(), half_meter);
  EXPECT_GT(full_meter.count(Work::hazard_test), 0U);
  EXPECT_LT(half_meter.count(Work::hazard_test), full_meter.count(Work::hazard_test));
}
// Row 40 of level ground with the pixels first..last unreliable.
imaging::Image<std::uint8_t> gap_in_row_40(int first, int last) {
  imaging::Image<std::uint8_t> reliable(64, 64, 1, 255);
  for (int x = first; x <= last; ++x)
    reliable(x, 40) = 0;
  return reliable;
}

TEST(FindZones, AnUnreliableGapNarrowerThanTheBridgeOnLevelGroundIsSeenGround) {
  const TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  ZoneOptions options = grid_options();
  options.bridged_gap_m = 0.25;
  // 3 pixels: the reliable ends 4 pixels = 0.20 m apart, under 0.25 m.
  const ZoneMap narrow = find_zones(t, gap_in_row_40(20, 22), options);
  EXPECT_EQ(narrow.count(Zone::traversable), 64U * 64U);
  // 5 pixels: the ends 0.30 m apart.
  const ZoneMap wide = find_zones(t, gap_in_row_40(20, 24), options);
  EXPECT_EQ(wide.count(Zone::unknown), 5U);
  EXPECT_EQ(wide.at(20, 40), Zone::unknown);
  EXPECT_EQ(wide.at(24, 40), Zone::unknown);
  // Bridging off.
  options.bridged_gap_m = 0.0;
  EXPECT_EQ(find_zones(t, gap_in_row_40(20, 22), options).count(Zone::unknown), 3U);
}

TEST(FindZones, AGapAtTheImageEdgeOrBetweenEndsAStepApartStaysUnknown) {
  ZoneOptions options = grid_options();
  options.bridged_gap_m = 0.25;
  const TerrainPoints level = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  EXPECT_EQ(find_zones(level, gap_in_row_40(0, 1), options).count(Zone::unknown), 2U);
  EXPECT_EQ(find_zones(level, gap_in_row_40(62, 63), options).count(Zone::unknown), 2U);
  // The ground right of column 22 is 0.35 m higher: the gap's ends differ by a step.
  const TerrainPoints stepped = grid_terrain(GridSpec{}, [](double, double left) {
    return left < testing::grid_left(GridSpec{}, 22) + 0.01 ? 0.35 : 0.0;
  });
  const ZoneMap zones = find_zones(stepped, gap_in_row_40(21, 22), options);
  EXPECT_EQ(zones.at(21, 40), Zone::unknown);
  EXPECT_EQ(zones.at(22, 40), Zone::unknown);
}

TEST(FindZones, RejectsBadOptionsAndAMaskOfAnotherSize) {
  const TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  ZoneOptions negative_step = grid_options();
  negative_step.max_step_m = -0.3;
  EXPECT_THROW(find_zones(t, {}, negative_step), std::invalid_argument);
  ZoneOptions vertical = grid_options();
  vertical.max_slope_deg = 90.0;
  EXPECT_THROW(find_zones(t, {}, vertical), std::invalid_argument);
  ZoneOptions no_width = grid_options();
  no_width.rover_half_width_m = std::nan("");
  EXPECT_THROW(find_zones(t, {}, no_width), std::invalid_argument);
  ZoneOptions no_cell = grid_options();
  no_cell.cell_m = 0.0;
  EXPECT_THROW(find_zones(t, {}, no_cell), std::invalid_argument);
  ZoneOptions loose = grid_options();
  loose.order_tolerance = 1.5;
  EXPECT_THROW(find_zones(t, {}, loose), std::invalid_argument);
  ZoneOptions negative_gap = grid_options();
  negative_gap.bridged_gap_m = -0.1;
  EXPECT_THROW(find_zones(t, {}, negative_gap), std::invalid_argument);
  const imaging::Image<std::uint8_t> small(10, 10, 1, 255);
  EXPECT_THROW(find_zones(t, small, grid_options()), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
