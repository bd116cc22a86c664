// Tests: polyline simplification and drive commands, by hand and from the paper's figure 4.

#include "marsokhod/nav/path/drive_commands.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace marsokhod::nav {
namespace {

// Points every `step` metres from a to b, a included, b excluded.
void append_segment(std::vector<GroundPoint>& points, GroundPoint a, GroundPoint b,
                    double step = 0.05) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const int n = static_cast<int>(std::round(length / step));
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / n;
    points.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
  }
}

TEST(SimplifyPolyline, KeepsTheCornerOfAnLShapedPath) {
  std::vector<GroundPoint> path;
  append_segment(path, {3.0, 0.0}, {6.0, 0.0});
  append_segment(path, {6.0, 0.0}, {6.0, 3.0});
  path.push_back({6.0, 3.0});
  const auto kept = simplify_polyline(path, 0.15);
  ASSERT_EQ(kept.size(), 3U);
  EXPECT_EQ(path[kept[1]], (GroundPoint{6.0, 0.0}));
}

TEST(SimplifyPolyline, DropsWigglesWithinTheToleranceAndKeepsLargerOnes) {
  std::vector<GroundPoint> small;
  std::vector<GroundPoint> large;
  for (int i = 0; i <= 100; ++i) {
    const double x = 3.0 + 0.1 * i;
    const double wiggle = (i % 2 == 0 ? 1.0 : -1.0);
    small.push_back({x, 0.06 * wiggle});                          // 0.12 m from the chord at most
    large.push_back({x, 0.40 * (1.0 - std::abs(i - 50) / 50.0)}); // a tent 0.40 m high
  }
  EXPECT_EQ(simplify_polyline(small, 0.15).size(), 2U);
  const auto kept = simplify_polyline(large, 0.15);
  ASSERT_EQ(kept.size(), 3U);
  EXPECT_EQ(kept[1], 50U);
}

TEST(PlanDrive, LShapedPathGivesTurnsAndStraightsByHand) {
  std::vector<GroundPoint> path;
  append_segment(path, {3.0, 0.0}, {6.0, 0.0});
  append_segment(path, {6.0, 0.0}, {6.0, 3.0});
  path.push_back({6.0, 3.0});
  const DrivePlan plan = plan_drive(path, DriveOptions{});
  EXPECT_DOUBLE_EQ(plan.start_m, 3.0);
  ASSERT_EQ(plan.fracture_m.size(), 1U);
  EXPECT_DOUBLE_EQ(plan.fracture_m[0], 6.0);
  EXPECT_NEAR(plan.target_m, std::sqrt(45.0), 1e-12);
  ASSERT_EQ(plan.commands.size(), 3U);
  // Rover centre to the start, then along the path, then a quarter turn left.
  EXPECT_NEAR(plan.commands[0].turn_deg, 0.0, 1e-9);
  EXPECT_NEAR(plan.commands[0].distance_m, 3.0, 1e-9);
  EXPECT_NEAR(plan.commands[1].turn_deg, 0.0, 1e-9);
  EXPECT_NEAR(plan.commands[1].distance_m, 3.0, 1e-9);
  EXPECT_NEAR(plan.commands[2].turn_deg, 90.0, 1e-9);
  EXPECT_NEAR(plan.commands[2].distance_m, 3.0, 1e-9);
  EXPECT_EQ(plan.ground_path.size(), path.size());
}

TEST(PlanDrive, ReproducesTheDistancesOfThePapersFigureFour) {
  // Fig. 4: start 2.90 m, one fracture point 4.60 m, target 12.70 m from the rover centre.
  // A path straight ahead to 4.60 m, then veering right to a point 12.70 m away.
  const double target_y = -2.0;
  const GroundPoint target{std::sqrt(12.70 * 12.70 - target_y * target_y), target_y};
  std::vector<GroundPoint> path;
  append_segment(path, {2.90, 0.0}, {4.60, 0.0});
  append_segment(path, {4.60, 0.0}, target);
  path.push_back(target);
  const DrivePlan plan = plan_drive(path, DriveOptions{});
  EXPECT_NEAR(plan.start_m, 2.90, 1e-12);
  ASSERT_EQ(plan.fracture_m.size(), 1U);
  EXPECT_NEAR(plan.fracture_m[0], 4.60, 1e-12);
  EXPECT_NEAR(plan.target_m, 12.70, 1e-12);
  ASSERT_EQ(plan.commands.size(), 3U);
  const double veer = std::atan2(target_y, target.x - 4.60) * 180.0 / 3.141592653589793;
  EXPECT_NEAR(plan.commands[2].turn_deg, veer, 1e-9);
  EXPECT_LT(plan.commands[2].turn_deg, 0.0); // clockwise: to the right
}

TEST(PlanDrive, TurnsAreWrappedToHalfATurn) {
  // Start behind-left then ahead: the turn from facing (-1, 1) to facing (+1, -1) is 180 deg.
  const std::vector<GroundPoint> path = {{-1.0, 1.0}, {1.0, -1.0}};
  const DrivePlan plan = plan_drive(path, DriveOptions{});
  ASSERT_EQ(plan.commands.size(), 2U);
  EXPECT_NEAR(plan.commands[0].turn_deg, 135.0, 1e-9);
  EXPECT_NEAR(std::abs(plan.commands[1].turn_deg), 180.0, 1e-9);
}

TEST(PlanDrive, ASinglePointIsOneLegAndAnEmptyPathIsAnError) {
  const std::vector<GroundPoint> one = {{2.5, 0.0}};
  const DrivePlan plan = plan_drive(one, DriveOptions{});
  EXPECT_DOUBLE_EQ(plan.start_m, 2.5);
  EXPECT_DOUBLE_EQ(plan.target_m, 2.5);
  EXPECT_TRUE(plan.fracture_m.empty());
  ASSERT_EQ(plan.commands.size(), 1U);
  EXPECT_THROW(plan_drive(std::vector<GroundPoint>{}, DriveOptions{}), std::invalid_argument);
  EXPECT_THROW(plan_drive(one, DriveOptions{0.0}), std::invalid_argument);
}

TEST(PlanDrive, PixelPathsUseTheTerrainsGroundPoints) {
  TerrainPoints t{imaging::Image<float>(4, 4, 1, 0.0F), imaging::Image<float>(4, 4, 1, 0.0F),
                  imaging::Image<float>(4, 4, 1, 0.0F), imaging::Image<float>(4, 4, 1, 0.0F), 16};
  t.forward(1, 3) = 3.0F;
  t.forward(1, 2) = 4.0F;
  t.left(1, 2) = 0.5F;
  const std::vector<PixelPoint> pixels = {{1, 3}, {1, 2}};
  const DrivePlan plan = plan_drive(t, pixels, DriveOptions{});
  ASSERT_EQ(plan.polyline.size(), 2U);
  EXPECT_EQ(plan.polyline[1], (GroundPoint{4.0, 0.5}));
  t.elevation(1, 2) = std::numeric_limits<float>::infinity();
  EXPECT_THROW(plan_drive(t, pixels, DriveOptions{}), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
