// Tests: the ground truth's obstacle map on flat ground, boxes and ramps, against node rules.

#include "marsokhod/world/terrain/obstacle_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace marsokhod::world {
namespace {

constexpr double kObstacleCell = 0.02;

/// An 8 m x 8 m field (401 nodes a side, node 200 at the origin) shaped by z(x, y).
HeightField field(const std::function<double(double, double)>& z) {
  HeightField height(401, 401, kObstacleCell, Eigen::Vector2d(-4.0, -4.0));
  for (int j = 0; j < height.ny(); ++j)
    for (int i = 0; i < height.nx(); ++i) {
      const Eigen::Vector2d p = height.node_position(i, j);
      height.at(i, j) = static_cast<float>(z(p.x(), p.y()));
    }
  return height;
}

/// A 2 m x 2 m box of the given height centred on the origin.
HeightField box(double box_height) {
  return field([=](double x, double y) {
    return std::abs(x) <= 1.0 + 1e-9 && std::abs(y) <= 1.0 + 1e-9 ? box_height : 0.0;
  });
}

HeightField ramp(double slope_deg, double azimuth_deg) {
  const double g = std::tan(slope_deg * std::numbers::pi / 180.0);
  const double a = azimuth_deg * std::numbers::pi / 180.0;
  return field([=](double x, double y) { return g * (x * std::cos(a) + y * std::sin(a)); });
}

int count_obstacles(const imaging::Image<std::uint8_t>& map) {
  int count = 0;
  for (std::size_t k = 0; k < map.size(); ++k)
    count += map.data()[k] == kObstacle;
  return count;
}

/// Node index of coordinate x on the 8 m field.
int node(double x) {
  return static_cast<int>(std::lround((x + 4.0) / kObstacleCell));
}

TEST(ObstacleMap, FlatGroundHasNoObstacles) {
  EXPECT_EQ(count_obstacles(obstacle_map(field([](double, double) { return 0.0; }), {})), 0);
}

TEST(ObstacleMap, GentleUndulationHasNoObstacles) {
  const HeightField gentle = field(
      [](double x, double y) { return 0.2 * std::sin(0.8 * x) * std::cos(0.6 * y) + 0.05 * x; });
  EXPECT_EQ(count_obstacles(obstacle_map(gentle, {})), 0);
}

TEST(ObstacleMap, BoxTallerThanTheStepLimitIsFlaggedAlongItsEdges) {
  const imaging::Image<std::uint8_t> map = obstacle_map(box(0.35), {});
  const int y = node(0.0);
  // On both sides of the east face, within the 0.30 m step baseline.
  EXPECT_EQ(map(node(1.0), y), kObstacle);
  EXPECT_EQ(map(node(1.02), y), kObstacle);
  EXPECT_EQ(map(node(0.72), y), kObstacle); // 0.28 m inside
  EXPECT_EQ(map(node(1.28), y), kObstacle); // 0.28 m outside
  // Beyond the baseline the ground is free again, inside and outside the box.
  EXPECT_EQ(map(node(1.36), y), 0);
  EXPECT_EQ(map(node(0.60), y), 0);
  EXPECT_EQ(map(node(0.0), y), 0);
  EXPECT_EQ(map(node(2.5), node(2.5)), 0);
  // The other faces too.
  EXPECT_EQ(map(node(-1.0), y), kObstacle);
  EXPECT_EQ(map(y, node(1.0)), kObstacle);
  EXPECT_EQ(map(y, node(-1.0)), kObstacle);
}

TEST(ObstacleMap, BoxLowerThanTheStepLimitIsNotFlagged) {
  EXPECT_EQ(count_obstacles(obstacle_map(box(0.25), {})), 0);
}

TEST(ObstacleMap, StepLimitIsTheCallersChoice) {
  LocomotionLimits small_wheels;
  small_wheels.max_step_m = 0.20;
  EXPECT_EQ(obstacle_map(box(0.25), small_wheels)(node(1.0), node(0.0)), kObstacle);
}

TEST(ObstacleMap, SteepRampIsFlaggedAndGentleRampIsNot) {
  for (const double azimuth : {0.0, 45.0, 100.0, 200.0}) {
    const imaging::Image<std::uint8_t> steep = obstacle_map(ramp(30.0, azimuth), {});
    EXPECT_EQ(count_obstacles(steep), 401 * 401) << "azimuth " << azimuth;
    const imaging::Image<std::uint8_t> gentle = obstacle_map(ramp(15.0, azimuth), {});
    EXPECT_EQ(count_obstacles(gentle), 0) << "azimuth " << azimuth;
  }
}

TEST(ObstacleMap, SlopeLimitSitsAtItsAngle) {
  EXPECT_EQ(count_obstacles(obstacle_map(ramp(24.0, 30.0), {})), 0);
  EXPECT_EQ(count_obstacles(obstacle_map(ramp(26.0, 30.0), {})), 401 * 401);
}

/// The documented rule evaluated literally, node by node (a reference for the fast filters).
imaging::Image<std::uint8_t> brute_force(const HeightField& h, const LocomotionLimits& limits) {
  const int s = static_cast<int>(std::lround(limits.step_baseline_m / h.cell_m()));
  const int d = static_cast<int>(std::lround(0.5 * limits.slope_baseline_m / h.cell_m()));
  const double tan_limit = std::tan(limits.max_slope_deg * std::numbers::pi / 180.0);
  imaging::Image<std::uint8_t> map(h.nx(), h.ny(), 1, 0);
  for (int j = 0; j < h.ny(); ++j)
    for (int i = 0; i < h.nx(); ++i) {
      bool obstacle = false;
      for (int b = std::max(0, j - s); b <= std::min(h.ny() - 1, j + s); ++b)
        for (int a = std::max(0, i - s); a <= std::min(h.nx() - 1, i + s); ++a)
          obstacle = obstacle || std::abs(h.at(a, b) - h.at(i, j)) > limits.max_step_m;
      const int i0 = std::max(0, i - d);
      const int i1 = std::min(h.nx() - 1, i + d);
      const int j0 = std::max(0, j - d);
      const int j1 = std::min(h.ny() - 1, j + d);
      double gx = 0.0;
      double gy = 0.0;
      for (const int b : {j0, j, j1})
        gx += (h.at(i1, b) - h.at(i0, b)) / (3.0 * (i1 - i0) * h.cell_m());
      for (const int a : {i0, i, i1})
        gy += (h.at(a, j1) - h.at(a, j0)) / (3.0 * (j1 - j0) * h.cell_m());
      obstacle = obstacle || std::hypot(gx, gy) > tan_limit;
      map(i, j) = obstacle ? kObstacle : 0;
    }
  return map;
}

TEST(ObstacleMap, MatchesTheRuleEvaluatedNodeByNode) {
  // A 3 m x 2.4 m patch of steps, bumps and slopes near both limits.
  HeightField rough(151, 121, kObstacleCell, Eigen::Vector2d(0.0, 0.0));
  for (int j = 0; j < rough.ny(); ++j)
    for (int i = 0; i < rough.nx(); ++i) {
      const double x = i * kObstacleCell;
      const double y = j * kObstacleCell;
      double z = 0.45 * std::sin(2.1 * x) * std::sin(1.7 * y + 0.3) + 0.1 * x;
      z += (x > 1.0 && x < 1.6 && y > 0.5 && y < 1.9) ? 0.27 : 0.0;
      z += std::hypot(x - 2.3, y - 0.8) < 0.25 ? 0.33 : 0.0;
      rough.at(i, j) = static_cast<float>(z);
    }
  const LocomotionLimits limits;
  const imaging::Image<std::uint8_t> fast = obstacle_map(rough, limits);
  const imaging::Image<std::uint8_t> reference = brute_force(rough, limits);
  int mismatches = 0;
  for (std::size_t k = 0; k < fast.size(); ++k)
    mismatches += fast.data()[k] != reference.data()[k];
  // Float rounding may flip a node sitting exactly on a limit; nothing more.
  EXPECT_LE(mismatches, 3);
  EXPECT_GT(count_obstacles(reference), 1000);
  EXPECT_LT(count_obstacles(reference), static_cast<int>(fast.size()) - 1000);
}

TEST(ObstacleMap, RejectsMeaninglessLimits) {
  const HeightField flat = field([](double, double) { return 0.0; });
  LocomotionLimits bad;
  bad.step_baseline_m = -0.3;
  EXPECT_THROW(obstacle_map(flat, bad), std::invalid_argument);
  bad = {};
  bad.max_slope_deg = 90.0;
  EXPECT_THROW(obstacle_map(flat, bad), std::invalid_argument);
  bad = {};
  bad.slope_baseline_m = std::nan("");
  EXPECT_THROW(obstacle_map(flat, bad), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::world
