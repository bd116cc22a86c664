// Tests: the poses along drive commands, by hand geometry.

#include "marsokhod/nav/path/drive_poses.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace marsokhod::nav {
namespace {

TEST(DrivePoses, TurnThenDriveEndsWhereTheCommandsLead) {
  const std::vector<DriveCommand> commands{{90.0, 1.0}};
  const std::pmr::vector<DrivePose> poses = drive_poses(commands);
  // The start, 45 turning poses of 2 degrees, 20 driving poses of 5 cm.
  ASSERT_EQ(poses.size(), 1u + 45u + 20u);
  EXPECT_TRUE(poses[45].turning);
  EXPECT_NEAR(poses[45].pose.heading_rad, std::numbers::pi / 2.0, 1e-12);
  EXPECT_FALSE(poses[46].turning);
  const DrivePose& last = poses.back();
  EXPECT_NEAR(last.pose.x, 0.0, 1e-12);
  EXPECT_NEAR(last.pose.y, 1.0, 1e-12);
  EXPECT_NEAR(last.along_m, 1.0, 1e-12);
  EXPECT_EQ(last.command, 0);
}

TEST(DrivePoses, LegsFollowEachOtherAndCountTheirIndex) {
  // Drive 2 m east, turn left 90 degrees, drive 1 m: the end is (2, 1).
  const std::vector<DriveCommand> commands{{0.0, 2.0}, {90.0, 1.0}};
  const std::pmr::vector<DrivePose> poses = drive_poses(commands, {0.5, 30.0});
  const DrivePose& last = poses.back();
  EXPECT_NEAR(last.pose.x, 2.0, 1e-12);
  EXPECT_NEAR(last.pose.y, 1.0, 1e-12);
  EXPECT_NEAR(last.along_m, 3.0, 1e-12);
  EXPECT_EQ(last.command, 1);
  // 1 start + 4 driving + 3 turning + 2 driving.
  EXPECT_EQ(poses.size(), 10u);
}

TEST(DrivePoses, RefuseNonPositiveStepsAndNonFiniteCommands) {
  const std::vector<DriveCommand> bad{{std::nan(""), 1.0}};
  EXPECT_THROW(drive_poses(bad), std::invalid_argument);
  const std::vector<DriveCommand> good{{0.0, 1.0}};
  EXPECT_THROW(drive_poses(good, {0.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(drive_poses(good, {0.05, -1.0}), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
