// Tests: the footprint judge on flat hand-made ground with obstacle nodes placed by hand. The
// footprint is 1.85 m x 1.20 m (half 0.925 m ahead and behind, 0.60 m to each side).

#include "world/hand_scenes.hpp"

#include "marsokhod/eval/terrain/footprint_judge.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace marsokhod::eval {
namespace {

world::Terrain flat_site() {
  return test::terrain_from(
      test::flat_field(6.0, 0.02), [](double, double) { return 0.5f; });
}

void put_obstacle(world::Terrain& terrain, double x, double y) {
  const world::HeightField& h = terrain.height;
  const int i = static_cast<int>(std::lround((x - h.origin().x()) / h.cell_m()));
  const int j = static_cast<int>(std::lround((y - h.origin().y()) / h.cell_m()));
  terrain.obstacles(i, j) = world::kObstacle;
}

const std::vector<nav::DriveCommand> kStraight3m{{0.0, 3.0}};

TEST(FootprintJudge, ClearGroundIsSafe) {
  const world::Terrain site = flat_site();
  EXPECT_FALSE(judge_footprint(site, test::level_placement(), kStraight3m).unsafe());
}

TEST(FootprintJudge, AnObstacleWithinHalfTheWidthOfTheLineIsHitByTheWheelsSide) {
  world::Terrain site = flat_site();
  put_obstacle(site, 1.5, 0.56);
  const FootprintVerdict verdict = judge_footprint(site, test::level_placement(), kStraight3m);
  ASSERT_TRUE(verdict.unsafe());
  EXPECT_NEAR(verdict.hit->x_m, 1.5, 1e-9);
  EXPECT_NEAR(verdict.hit->y_m, 0.56, 1e-9);
  // The front edge (0.925 m ahead of the centre) reaches x = 1.5 once the centre passes
  // 0.575 m: the first pose at or beyond that, on a 5 cm step, is 0.60 m.
  EXPECT_NEAR(verdict.hit->pose.along_m, 0.60, 1e-9);
  EXPECT_FALSE(verdict.hit->pose.turning);
}

TEST(FootprintJudge, AnObstacleJustBeyondHalfTheWidthIsPassed) {
  world::Terrain site = flat_site();
  put_obstacle(site, 1.5, 0.64);
  put_obstacle(site, 1.5, -0.64);
  EXPECT_FALSE(judge_footprint(site, test::level_placement(), kStraight3m).unsafe());
}

TEST(FootprintJudge, TheFrontAtTheEndOfTheDriveCounts) {
  world::Terrain site = flat_site();
  put_obstacle(site, 3.90, 0.0); // the front stops at 3.925 m
  const FootprintVerdict verdict = judge_footprint(site, test::level_placement(), kStraight3m);
  ASSERT_TRUE(verdict.unsafe());
  EXPECT_NEAR(verdict.hit->pose.along_m, 3.0, 1e-9);
  world::Terrain beyond = flat_site();
  put_obstacle(beyond, 3.96, 0.0);
  EXPECT_FALSE(judge_footprint(beyond, test::level_placement(), kStraight3m).unsafe());
}

TEST(FootprintJudge, TurningOnTheSpotSweepsTheCornersTowardsTheTurn) {
  // (0.75, 0.75) lies outside the footprint facing east, 1.06 m from the centre, within the
  // corners' reach (1.10 m). Turning left brings it under the front left of the rectangle
  // (at 12 degrees it is 0.89 m ahead and 0.58 m left); turning right moves the
  // rectangle away from it.
  world::Terrain site = flat_site();
  put_obstacle(site, 0.75, 0.75);
  const std::vector<nav::DriveCommand> left{{30.0, 0.05}};
  const FootprintVerdict verdict = judge_footprint(site, test::level_placement(), left);
  ASSERT_TRUE(verdict.unsafe());
  EXPECT_TRUE(verdict.hit->pose.turning);
  const std::vector<nav::DriveCommand> right{{-30.0, 0.05}};
  EXPECT_FALSE(judge_footprint(site, test::level_placement(), right).unsafe());
}

TEST(FootprintJudge, TheCommandsRunInTheRoversOwnFrame) {
  // The rover at (2, 3) facing north: 1.5 m ahead and 0.56 m to its left is world (1.44, 4.5).
  world::Terrain site = flat_site();
  put_obstacle(site, 2.0 - 0.56, 3.0 + 1.5);
  const world::RoverPlacement placement =
      world::place_rover(site.height, world::RoverPose{2.0, 3.0, 90.0});
  const FootprintVerdict verdict = judge_footprint(site, placement, kStraight3m);
  ASSERT_TRUE(verdict.unsafe());
  EXPECT_NEAR(verdict.hit->x_m, 1.5, 1e-6);
  EXPECT_NEAR(verdict.hit->y_m, 0.56, 1e-6);
  EXPECT_NEAR(verdict.hit->range_m, std::hypot(1.5, 0.56), 1e-6);
}

TEST(FootprintJudge, DrivingOffTheSiteIsUnsafe) {
  const world::Terrain site = flat_site(); // 6 m each way from the origin
  const std::vector<nav::DriveCommand> long_drive{{0.0, 5.5}};
  const FootprintVerdict verdict = judge_footprint(site, test::level_placement(), long_drive);
  ASSERT_TRUE(verdict.unsafe());
  EXPECT_GT(verdict.hit->x_m, 6.0);
}

TEST(FootprintJudge, DescribesWhereAndWhen) {
  FootprintHit hit;
  hit.x_m = 4.21;
  hit.y_m = -0.62;
  hit.range_m = 4.26;
  hit.pose.along_m = 3.9;
  hit.pose.command = 1;
  EXPECT_EQ(describe(hit),
            "obstacle 4.26 m away (4.21 ahead, 0.62 right), 3.90 m into the drive, leg 2 driving");
}

} // namespace
} // namespace marsokhod::eval
