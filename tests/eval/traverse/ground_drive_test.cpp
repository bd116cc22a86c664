// Tests: driving commands on hand-made true ground, where the inclinometer's readings and the
// footprint's reach are hand geometry (wheelbase 1.5 m, track 1.0 m, footprint 1.85 m x
// 1.20 m: it reaches 0.925 m ahead of the centre).

#include "world/hand_scenes.hpp"

#include "marsokhod/eval/traverse/ground_drive.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace marsokhod::eval {
namespace {

world::Terrain ground(const std::function<double(double, double)>& height) {
  world::HeightField field = test::flat_field(8.0, 0.02);
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i) {
      const Eigen::Vector2d p = field.node_position(i, j);
      field.at(i, j) = static_cast<float>(height(p.x(), p.y()));
    }
  return test::terrain_from(std::move(field), [](double, double) { return 0.5f; });
}

double rise(double degrees) {
  return std::tan(degrees * std::numbers::pi / 180.0);
}

const std::vector<nav::DriveCommand> kStraight6m{{0.0, 6.0}};

TEST(GroundDrive, TiltOfPitchOrRollAloneIsThatAngle) {
  EXPECT_NEAR(tilt_deg(20.0, 0.0), 20.0, 1e-9);
  EXPECT_NEAR(tilt_deg(0.0, -25.0), 25.0, 1e-9);
  EXPECT_NEAR(tilt_deg(0.0, 0.0), 0.0, 1e-9);
}

TEST(GroundDrive, LevelGroundDrivesTheWholeCommand) {
  const world::Terrain site = ground([](double, double) { return 0.0; });
  const GroundDrive drive = drive_on_ground(site, {0.0, 0.0, 0.0}, kStraight6m, {}, {});
  EXPECT_FALSE(drive.unsafe);
  EXPECT_FALSE(drive.emergency_stop);
  EXPECT_NEAR(drive.driven_m, 6.0, 1e-9);
  EXPECT_NEAR(drive.end.x, 6.0, 1e-9);
  EXPECT_NEAR(drive.end.y, 0.0, 1e-9);
}

// A 22 deg ramp from x = 3: the pitch stays 0 until the front axle (0.75 m ahead) reaches it
// and is the ramp's once the rear axle is on it, so the 20 deg threshold is crossed between
// 2.25 m and 3.75 m, and read within one 0.25 m reading interval after.
TEST(GroundDrive, InclinometerStopsTheRoverClimbingARampSteeperThanTheThreshold) {
  const world::Terrain site =
      ground([](double x, double) { return rise(22.0) * std::max(0.0, x - 3.0); });
  const GroundDrive drive = drive_on_ground(site, {0.0, 0.0, 0.0}, kStraight6m, {}, {});
  ASSERT_FALSE(drive.unsafe) << *drive.unsafe;
  EXPECT_TRUE(drive.emergency_stop);
  EXPECT_GT(drive.driven_m, 2.25);
  EXPECT_LE(drive.driven_m, 3.75 + 0.25 + 1e-9);
  EXPECT_GT(drive.tilt_deg, 20.0);
  EXPECT_LE(drive.tilt_deg, 22.0 + 1e-6);
}

// Ground tilting sideways from 1 m ahead to 22 deg over 2 m, one side up.
world::Terrain side_slope(double sign) {
  return ground([sign](double x, double y) {
    return sign * rise(22.0) * y * std::clamp((x - 1.0) / 2.0, 0.0, 1.0);
  });
}

TEST(GroundDrive, EmergencyStopNamesTheSideThatRose) {
  const GroundDrive left = drive_on_ground(side_slope(1.0), {0.0, 0.0, 0.0}, kStraight6m, {}, {});
  ASSERT_TRUE(left.emergency_stop);
  EXPECT_EQ(left.risen_side, nav::Side::left);
  EXPECT_GT(left.tilt_deg, 20.0);

  const GroundDrive right = drive_on_ground(side_slope(-1.0), {0.0, 0.0, 0.0}, kStraight6m, {}, {});
  ASSERT_TRUE(right.emergency_stop);
  EXPECT_EQ(right.risen_side, nav::Side::right);
}

// Standing on a 22 deg side slope (after an emergency stop), the rover turns and drives on it:
// the tilt does not rise, so no new emergency.
TEST(GroundDrive, RoverAlreadyOverTheThresholdIsNotStoppedAgain) {
  const world::Terrain plane = ground([](double, double y) { return rise(22.0) * y; });
  const std::vector<nav::DriveCommand> turn_and_go{{-30.0, 2.0}};
  const GroundDrive drive = drive_on_ground(plane, {0.0, 0.0, 0.0}, turn_and_go, {}, {});
  EXPECT_FALSE(drive.emergency_stop);
  EXPECT_FALSE(drive.unsafe);
  EXPECT_NEAR(drive.driven_m, 2.0, 1e-9);
}

// A 0.4 m box (over the 0.30 m step) from x = 4: the obstacle map marks the ground within one
// step baseline (0.30 m) of it, and the footprint's front reaches that when the centre is
// 0.925 m short of it, within one 5 cm pose.
TEST(GroundDrive, FootprintOnATrueObstacleIsUnsafeWhereItFirstTouches) {
  world::HeightField field = test::flat_field(8.0, 0.02);
  test::raise_box(field, 4.0, 4.5, -0.2, 0.2, 0.4);
  const world::Terrain site =
      test::terrain_from(std::move(field), [](double, double) { return 0.5f; });
  const GroundDrive drive = drive_on_ground(site, {0.0, 0.0, 0.0}, kStraight6m, {}, {});
  ASSERT_TRUE(drive.unsafe);
  const double first_obstacle_x = 4.0 - world::LocomotionLimits{}.step_baseline_m;
  EXPECT_NEAR(drive.driven_m, first_obstacle_x - 0.925, 0.05 + site.settings.cell_m);
  EXPECT_NEAR(drive.unsafe_at.x(), drive.driven_m, 1e-9);
}

TEST(GroundDrive, DriveEndsAtTheFirstReadingWithinTheGoalTolerance) {
  const world::Terrain site = ground([](double, double) { return 0.0; });
  GroundDriveLimits limits;
  limits.goal = Eigen::Vector2d(2.0, 0.0);
  limits.goal_tolerance_m = 0.5;
  const GroundDrive drive = drive_on_ground(site, {0.0, 0.0, 0.0}, kStraight6m, {}, limits);
  EXPECT_TRUE(drive.at_goal);
  EXPECT_NEAR(drive.driven_m, 1.5, 1e-9); // readings every 0.25 m: 1.5 m is the first within
}

TEST(GroundDrive, TurnsAreExecutedInTheWorldFrame) {
  const world::Terrain site = ground([](double, double) { return 0.0; });
  const std::vector<nav::DriveCommand> left_then_ahead{{90.0, 2.0}};
  const GroundDrive drive = drive_on_ground(site, {1.0, -1.0, 0.0}, left_then_ahead, {}, {});
  EXPECT_NEAR(drive.end.x, 1.0, 1e-9);
  EXPECT_NEAR(drive.end.y, 1.0, 1e-9);
  EXPECT_NEAR(drive.end.heading_deg, 90.0, 1e-9);
  EXPECT_NEAR(drive.turned_deg, 90.0, 1e-9);
}

} // namespace
} // namespace marsokhod::eval
