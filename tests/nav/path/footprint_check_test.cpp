// Tests: the footprint check of drive commands against step and slope points, on hand-made
// terrain where the footprint's reach is hand geometry.

#include "nav/terrain_grid.hpp"

#include "marsokhod/nav/path/footprint_check.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace marsokhod::nav {
namespace {

using testing::grid_terrain;
using testing::GridSpec;
using testing::long_grid;

// The long grid: column 20 straight ahead, 5 cm a pixel; row y is 2.0 + 0.05 (207 - y) m ahead.
int column_at(double left_m) {
  return 20 - static_cast<int>(std::lround(left_m / 0.05));
}
int row_at(double forward_m) {
  return 207 - static_cast<int>(std::lround((forward_m - 2.0) / 0.05));
}

struct FootprintScene {
  TerrainPoints terrain = grid_terrain(long_grid(), [](double, double) { return 0.0; });
  ZoneMap zones{imaging::Image<std::uint8_t>(41, 208, 1, 0), {}};

  void mark(double forward_m, double left_m, Zone zone = Zone::step) {
    zones.zone(column_at(left_m), row_at(forward_m)) = static_cast<std::uint8_t>(zone);
  }
  std::pmr::vector<FootprintConflict> conflicts(const std::vector<DriveCommand>& commands) const {
    return footprint_conflicts(ResidentTerrain(terrain), zones, commands, imaging::Chassis{}, 16);
  }
};

// The default chassis: 1.85 m long, 1.20 m wide, so the footprint reaches 0.925 m ahead of the
// rover's centre and 0.60 m to either side.
TEST(FootprintConflicts, FindsAStepLessThanHalfALengthBeyondTheEndOfTheDrive) {
  FootprintScene inside;
  inside.mark(5.90, 0.0);
  const auto conflicts = inside.conflicts({{0.0, 5.0}});
  ASSERT_EQ(conflicts.size(), 1U);
  EXPECT_NEAR(conflicts[0].hazard.x, 5.90, 1e-5);
  EXPECT_EQ(conflicts[0].command, 0);
  EXPECT_FALSE(conflicts[0].turning);
  FootprintScene beyond;
  beyond.mark(6.00, 0.0);
  EXPECT_TRUE(beyond.conflicts({{0.0, 5.0}}).empty());
}

TEST(FootprintConflicts, FindsAStepWithinHalfAWidthOfTheDriveAndNotBeyond) {
  FootprintScene beside;
  beside.mark(3.0, 0.55);
  EXPECT_EQ(beside.conflicts({{0.0, 5.0}}).size(), 1U);
  FootprintScene clear;
  clear.mark(3.0, 0.65);
  clear.mark(3.0, -0.65, Zone::slope);
  EXPECT_TRUE(clear.conflicts({{0.0, 5.0}}).empty());
  FootprintScene slope;
  slope.mark(3.0, -0.55, Zone::slope);
  EXPECT_EQ(slope.conflicts({{0.0, 5.0}}).size(), 1U);
}

// A point 1.06 m from the pivot at 45 degrees: outside the footprint before the turn (0.75 m to
// the side) and after it (0.75 m to the other side), under its front corner (0.925, 0.60) only
// between headings of about 10.6 and 15.7 degrees.
TEST(FootprintConflicts, FindsAStepOnlyTheCornerSweepsTurningOnTheSpot) {
  FootprintScene scene;
  scene.mark(4.75, 0.75);
  const auto conflicts = scene.conflicts({{0.0, 4.0}, {90.0, 3.0}});
  ASSERT_EQ(conflicts.size(), 1U);
  EXPECT_EQ(conflicts[0].command, 1);
  EXPECT_TRUE(conflicts[0].turning);
  EXPECT_TRUE(scene.conflicts({{0.0, 4.0}, {0.0, 0.5}}).empty()) << "without the turn";
}

// Given points, the same geometry: a 5 m drive's footprint reaches from 0.925 m behind the
// centre to 5.925 m ahead, 0.60 m to either side.
TEST(FootprintCovers, FindsTheGivenPointsUnderTheDriveInTheirOrder) {
  const std::vector<GroundPoint> points{{1.0, 0.0},  {6.0, 0.0},    {3.0, 0.65},
                                        {5.90, 0.0}, {-0.90, 0.55}, {-1.0, 0.0}};
  const auto covered =
      footprint_covers(points, std::vector<DriveCommand>{{0.0, 5.0}}, imaging::Chassis{}, 16);
  ASSERT_EQ(covered.size(), 3U);
  EXPECT_NEAR(covered[0].hazard.x, 1.0, 1e-12);
  EXPECT_NEAR(covered[1].hazard.x, 5.90, 1e-12);
  EXPECT_NEAR(covered[2].hazard.x, -0.90, 1e-12);
  EXPECT_EQ(
      footprint_covers(points, std::vector<DriveCommand>{{0.0, 5.0}}, imaging::Chassis{}, 1).size(),
      1U)
      << "at most the limit";
}

TEST(FootprintConflicts, IgnoresMarginAndUnknownGround) {
  FootprintScene scene;
  scene.mark(3.0, 0.0, Zone::margin);
  scene.mark(3.5, 0.0, Zone::unknown);
  EXPECT_TRUE(scene.conflicts({{0.0, 5.0}}).empty());
}

TEST(FootprintConflicts, StopsAtTheLimitNearestFirstAndCountsItsWork) {
  FootprintScene scene;
  for (const double forward : {3.0, 3.5, 4.0, 4.5})
    scene.mark(forward, 0.0);
  CountingMeter work;
  const std::vector<DriveCommand> commands{{0.0, 5.0}};
  const auto two =
      footprint_conflicts(ResidentTerrain(scene.terrain), scene.zones, commands, {}, 2, work);
  ASSERT_EQ(two.size(), 2U);
  EXPECT_NEAR(two[0].hazard.x, 3.0, 1e-5);
  EXPECT_NEAR(two[1].hazard.x, 3.5, 1e-5);
  // Rows from the bottom (2.0 m) up to the second conflict (3.5 m): 31 rows of 41 pixels.
  EXPECT_EQ(work.count(Work::footprint_scan), 31U * 41U);
  EXPECT_EQ(work.count(Work::footprint_test), 2U) << "one leg, no turn, per step point";
}

} // namespace
} // namespace marsokhod::nav
