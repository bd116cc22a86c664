// Scoring one site on hand-built zone maps and ground truth: counts, zones, errors, paths.
#include "nav/terrain_grid.hpp"

#include "marsokhod/eval/terrain/terrain_scoring.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace marsokhod::eval {
namespace {

// A 4 x 1 strip: every pixel seen by both cameras, 5 m away (band 2-6 m).
world::GroundTruth strip_truth() {
  world::GroundTruth truth = world::GroundTruth::unknown(4, 1);
  for (int x = 0; x < 4; ++x) {
    truth.range(x, 0) = 5.0F;
    truth.visible(x, 0) = truth.valid(x, 0) = 255;
  }
  return truth;
}

nav::ZoneMap strip_zones(std::initializer_list<nav::Zone> zones) {
  nav::ZoneMap map{imaging::Image<std::uint8_t>(4, 1), {}};
  int x = 0;
  for (const nav::Zone z : zones)
    map.zone(x++, 0) = static_cast<std::uint8_t>(z);
  return map;
}

TEST(ScoreZones, CountsObstaclesProhibitedAndFreeGroundProhibitedByBand) {
  world::GroundTruth truth = strip_truth();
  truth.obstacles(0, 0) = truth.obstacles(1, 0) = 255;
  // Pixel 0: an obstacle we prohibit by its margin; 1: an obstacle we miss; 2: free ground we
  // prohibit; 3: free ground we leave open.
  const nav::ZoneMap ours = strip_zones(
      {nav::Zone::margin, nav::Zone::traversable, nav::Zone::step, nav::Zone::traversable});
  const nav::ZoneMap theirs = strip_zones(
      {nav::Zone::step, nav::Zone::step, nav::Zone::traversable, nav::Zone::traversable});
  const BandTable table = score_zones(ours, theirs, truth);
  EXPECT_EQ(table[0].obstacle_pixels, 2U);
  EXPECT_EQ(table[0].obstacles_prohibited, 1U);
  EXPECT_EQ(table[0].free_pixels, 2U);
  EXPECT_EQ(table[0].free_prohibited, 1U);
  EXPECT_EQ(table[0].free_prohibited_as[static_cast<std::size_t>(nav::Zone::step)], 1U);
  EXPECT_EQ(table[0].free_prohibited_as[static_cast<std::size_t>(nav::Zone::margin)], 0U);
  EXPECT_EQ(table[1].obstacle_pixels + table[2].free_pixels, 0U);
  // The detector alone: the margin is no hazard.
  const BandTable hazards = score_hazards(ours, truth);
  EXPECT_EQ(hazards[0].obstacles_prohibited, 0U);
  EXPECT_EQ(hazards[0].free_prohibited, 1U);
}

TEST(ScoreZones, FreeGroundInsideTheTruthsMarginAndPixelsOneCameraMissesAreNotScored) {
  world::GroundTruth truth = strip_truth();
  truth.valid(3, 0) = 0; // occluded from the right camera
  const nav::ZoneMap ours =
      strip_zones({nav::Zone::step, nav::Zone::step, nav::Zone::step, nav::Zone::step});
  const nav::ZoneMap theirs = strip_zones(
      {nav::Zone::margin, nav::Zone::traversable, nav::Zone::traversable, nav::Zone::traversable});
  const BandTable table = score_zones(ours, theirs, truth);
  EXPECT_EQ(table[0].free_pixels, 2U);
  EXPECT_EQ(table[0].free_prohibited, 2U);
}

TEST(GroundTruthZones, GroundOnlyOneCameraSeesIsUnknownAndObstaclesAreSteps) {
  world::GroundTruth truth = strip_truth();
  truth.valid(2, 0) = 0; // the left camera sees it, the right one does not
  truth.obstacles(0, 0) = 255;
  nav::TerrainPoints terrain{
      imaging::Image<float>(4, 1, 1, 5.0F), imaging::Image<float>(4, 1, 1, 0.0F),
      imaging::Image<float>(4, 1, 1, 0.0F), imaging::Image<float>(4, 1, 1, 5.0F), 4};
  for (int x = 0; x < 4; ++x)
    terrain.left(x, 0) = 0.4F * static_cast<float>(x); // 0.4 m apart: beyond each other's margin
  nav::ZoneOptions options;
  options.rover_half_width_m = 0.3;
  const nav::ZoneMap zones = ground_truth_zones(terrain, truth, options);
  EXPECT_EQ(zones.at(0, 0), nav::Zone::step);
  EXPECT_EQ(zones.at(1, 0), nav::Zone::traversable);
  EXPECT_EQ(zones.at(2, 0), nav::Zone::unknown);
  EXPECT_EQ(zones.at(3, 0), nav::Zone::traversable);
}

TEST(ElevationErrors, AreTakenOnJudgedFreeGroundWhereTheNavigationHasAPoint) {
  world::GroundTruth truth = strip_truth();
  truth.range(3, 0) = 7.0F; // band 6-10 m
  truth.obstacles(1, 0) = 255;
  const float kInf = std::numeric_limits<float>::infinity();
  nav::TerrainPoints ours{imaging::Image<float>(4, 1), imaging::Image<float>(4, 1),
                          imaging::Image<float>(4, 1), imaging::Image<float>(4, 1), 3};
  for (int x = 0; x < 4; ++x) {
    truth.elevation(x, 0) = 0.10F;
    ours.elevation(x, 0) = 0.10F + 0.01F * static_cast<float>(x + 1);
  }
  ours.elevation(2, 0) = kInf; // no point: not scored
  nav::ZoneMap zones{imaging::Image<std::uint8_t>(4, 1, 1, 0), {}};
  std::array<std::vector<float>, kTerrainBands.size()> errors;
  collect_elevation_errors(ours, zones, truth, errors);
  // Pixel 0 (0.01 m off) in 2-6 m; pixel 1 is an obstacle; pixel 3 (0.04 m off) in 6-10 m.
  ASSERT_EQ(errors[0].size(), 1U);
  EXPECT_NEAR(errors[0][0], 0.01, 1e-6);
  ASSERT_EQ(errors[1].size(), 1U);
  EXPECT_NEAR(errors[1][0], 0.04, 1e-6);
  EXPECT_TRUE(errors[2].empty());
  // A point the zone rules set aside as unknown (out of order, say) is not scored.
  zones.zone(3, 0) = static_cast<std::uint8_t>(nav::Zone::unknown);
  std::array<std::vector<float>, kTerrainBands.size()> judged;
  collect_elevation_errors(ours, zones, truth, judged);
  EXPECT_EQ(judged[0].size(), 1U);
  EXPECT_TRUE(judged[1].empty());
}

// A 5 x 10 view of level ground, 0.1 m a pixel: row 9 is 2.0 m ahead, row 0 2.9 m; column 2
// straight ahead. The path starts 2.5 m ahead (row 4) and runs straight on.
struct StraightAhead {
  nav::testing::GridSpec grid{5, 10, 0.1, 2.0};
  nav::TerrainPoints terrain = nav::testing::grid_terrain(grid, [](double, double) { return 0.0; });
  world::GroundTruth truth = world::GroundTruth::unknown(5, 10);
  nav::PathPlan plan;
  StraightAhead() {
    plan.start = {2, 4};
    plan.pixels = {{2, 4}, {2, 3}, {2, 2}, {2, 1}, {2, 0}};
  }
};

TEST(CrossesObstacle, IsTrueWhenAnyPathPixelSeesAnObstacle) {
  StraightAhead site;
  EXPECT_FALSE(crosses_obstacle(site.plan, site.terrain, site.truth));
  site.truth.obstacles(2, 1) = 255;
  EXPECT_TRUE(crosses_obstacle(site.plan, site.terrain, site.truth));
}

TEST(CrossesObstacle, IsTrueWhenTheDriveToTheStartSeesAnObstacle) {
  StraightAhead site;
  // 0.2 m beside the line from the rover to the start: the rover's centre passes it by.
  site.truth.obstacles(0, 7) = 255;
  EXPECT_FALSE(crosses_obstacle(site.plan, site.terrain, site.truth));
  // 2.2 m straight ahead, short of the start: the rover drives over it to reach the start.
  site.truth.obstacles(2, 7) = 255;
  EXPECT_TRUE(crosses_obstacle(site.plan, site.terrain, site.truth));
  // Where the true terrain has no point at the start, only the path's own pixels count.
  site.terrain.elevation(2, 4) = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(crosses_obstacle(site.plan, site.terrain, site.truth));
}

TEST(Percent, IsNotANumberForAnEmptyWhole) {
  EXPECT_DOUBLE_EQ(percent(1, 4), 25.0);
  EXPECT_TRUE(std::isnan(percent(0, 0)));
}

} // namespace
} // namespace marsokhod::eval
