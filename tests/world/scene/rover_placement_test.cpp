// Tests: the rover placement on the terrain (height, pitch, roll) by hand geometry.

#include "support/test_files.hpp"

#include "marsokhod/world/scene/rover_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace marsokhod::world {
namespace {

using test_support::kDegree;

/// A 10 m x 10 m plane z = z0 + gx x + gy y.
HeightField plane(double z0, double gx, double gy) {
  HeightField height(501, 501, 0.02, Eigen::Vector2d(-5.0, -5.0));
  for (int j = 0; j < 501; ++j)
    for (int i = 0; i < 501; ++i) {
      const Eigen::Vector2d p = height.node_position(i, j);
      height.at(i, j) = static_cast<float>(z0 + gx * p.x() + gy * p.y());
    }
  return height;
}

TEST(RoverPlacement, LevelGroundGivesZeroAttitude) {
  const RoverPlacement placed = place_rover(plane(0.7, 0.0, 0.0), {1.0, -2.0, 30.0});
  EXPECT_NEAR(placed.ground_z, 0.7, 1e-6);
  EXPECT_NEAR(placed.attitude.pitch_deg, 0.0, 1e-9);
  EXPECT_NEAR(placed.attitude.roll_deg, 0.0, 1e-9);
}

TEST(RoverPlacement, TenDegreeSlopeEastwardsForTheFourHeadings) {
  // The ground rises 10 degrees towards the east (x).
  const HeightField ground = plane(0.0, std::tan(10.0 * kDegree), 0.0);
  struct Case {
    double heading_deg;
    double pitch_deg; // nose up when heading uphill
    double roll_deg;  // positive when the right side is lower
  };
  // Heading north, east is on the right: the right side is higher, roll negative.
  for (const Case& c : {Case{0.0, 10.0, 0.0}, Case{90.0, 0.0, -10.0}, Case{180.0, -10.0, 0.0},
                        Case{270.0, 0.0, 10.0}}) {
    const RoverPlacement placed = place_rover(ground, {0.5, 0.5, c.heading_deg});
    EXPECT_NEAR(placed.attitude.pitch_deg, c.pitch_deg, 1e-4) << "heading " << c.heading_deg;
    EXPECT_NEAR(placed.attitude.roll_deg, c.roll_deg, 1e-4) << "heading " << c.heading_deg;
    EXPECT_NEAR(placed.ground_z, 0.5 * std::tan(10.0 * kDegree), 1e-6);
  }
}

TEST(RoverPlacement, ObliqueHeadingsMatchTheNormalOfTheTiltedPlane) {
  // For the documented body frame (roll about x first, then pitch about y, nose up), the body
  // z axis, expressed in the level frame, is (-sin p cos r, -sin r, cos p cos r): it must be
  // the plane's unit normal. Compute that normal by hand in the level frame for each heading.
  const double gx = 0.15;
  const double gy = -0.08;
  const HeightField ground = plane(1.0, gx, gy);
  for (const double heading : {0.0, 30.0, 45.0, 123.0, 250.0, 333.0}) {
    const double h = heading * kDegree;
    const Eigen::Vector3d normal_world = Eigen::Vector3d(-gx, -gy, 1.0).normalized();
    // Level frame: x forward (cos h, sin h), y left (-sin h, cos h), z up.
    const Eigen::Vector3d n(normal_world.x() * std::cos(h) + normal_world.y() * std::sin(h),
                            -normal_world.x() * std::sin(h) + normal_world.y() * std::cos(h),
                            normal_world.z());
    const double expected_roll = -std::asin(n.y()) / kDegree;
    const double expected_pitch = std::atan2(-n.x(), n.z()) / kDegree;
    const RoverPlacement placed = place_rover(ground, {-1.0, 2.0, heading});
    EXPECT_NEAR(placed.attitude.pitch_deg, expected_pitch, 1e-4) << "heading " << heading;
    EXPECT_NEAR(placed.attitude.roll_deg, expected_roll, 1e-4) << "heading " << heading;
    EXPECT_NEAR(placed.ground_z, 1.0 + gx * -1.0 + gy * 2.0, 1e-6);
  }
}

TEST(RoverPlacement, AttitudeTurnsTheRigsBodyFrameOntoTheGround) {
  // The rig's own body rotation (imaging::StereoRig) for the attitude found must carry the level
  // z axis onto the ground's normal, expressed in the level frame.
  const double gx = -0.12;
  const double gy = 0.21;
  const HeightField ground = plane(0.0, gx, gy);
  const imaging::StereoRig rig;
  for (const double heading : {10.0, 100.0, 215.0}) {
    const RoverPlacement placed = place_rover(ground, {0.5, -0.5, heading});
    const Eigen::Matrix3d body = rig.camera_to_level(imaging::Eye::left, placed.attitude).linear() *
                                 rig.camera_to_level(imaging::Eye::left).linear().transpose();
    const Eigen::Vector3d normal_world = Eigen::Vector3d(-gx, -gy, 1.0).normalized();
    const Eigen::Vector3d normal_level = placed.level_to_world.linear().transpose() * normal_world;
    EXPECT_NEAR((body * Eigen::Vector3d::UnitZ() - normal_level).norm(), 0.0, 1e-6)
        << "heading " << heading;
  }
}

TEST(RoverPlacement, LevelFrameSitsOnTheGroundTurnedByTheHeading) {
  const HeightField ground = plane(0.3, 0.05, 0.0);
  const RoverPlacement placed = place_rover(ground, {2.0, 1.0, 120.0});
  const Eigen::Vector3d origin = placed.level_to_world * Eigen::Vector3d::Zero();
  EXPECT_NEAR((origin - Eigen::Vector3d(2.0, 1.0, 0.3 + 0.05 * 2.0)).norm(), 0.0, 1e-6);
  const Eigen::Vector3d forward = placed.level_to_world.linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(
      (forward - Eigen::Vector3d(std::cos(120.0 * kDegree), std::sin(120.0 * kDegree), 0.0)).norm(),
      0.0, 1e-12);
  const Eigen::Vector3d up = placed.level_to_world.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR((up - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
}

TEST(RoverPlacement, ABlockUnderTheFrontWheelsPitchesTheNoseUp) {
  // Heading east; a 0.2 m block under the front axle only (x = 0.75 +- 0.1).
  HeightField ground = plane(0.0, 0.0, 0.0);
  for (int j = 0; j < ground.ny(); ++j)
    for (int i = 0; i < ground.nx(); ++i)
      if (std::abs(ground.node_position(i, j).x() - 0.75) <= 0.1)
        ground.at(i, j) = 0.2f;
  const RoverPlacement placed = place_rover(ground, {0.0, 0.0, 0.0});
  // Front pair 0.2 m above the rear pair over the 1.5 m wheelbase.
  EXPECT_NEAR(placed.attitude.pitch_deg, std::atan(0.2 / 1.5) / kDegree, 1e-4);
  EXPECT_NEAR(placed.attitude.roll_deg, 0.0, 1e-9);
}

TEST(RoverPlacement, WheelContactsFollowWheelbaseAndTrack) {
  const auto wheels = wheel_contacts({0.0, 0.0, 90.0}, {2.0, 1.2});
  // Heading north: front is +y, left is -x.
  EXPECT_NEAR((wheels[0] - Eigen::Vector2d(-0.6, 1.0)).norm(), 0.0, 1e-12); // front left
  EXPECT_NEAR((wheels[4] - Eigen::Vector2d(0.6, 0.0)).norm(), 0.0, 1e-12);  // middle right
  EXPECT_NEAR((wheels[5] - Eigen::Vector2d(0.6, -1.0)).norm(), 0.0, 1e-12); // rear right
}

TEST(RoverPlacement, RejectsAPoseOffTheTerrainOrABadChassis) {
  const HeightField ground = plane(0.0, 0.0, 0.0);
  EXPECT_THROW(place_rover(ground, {7.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(place_rover(ground, {0.0, 0.0, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(place_rover(ground, {0.0, 0.0, 0.0}, {0.0, 1.0}), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::world
