// Tests: the height field's grid, bilinear heights, normals and border clamping.

#include "marsokhod/world/terrain/height_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::world {
namespace {

/// A 5 x 4 grid of 0.5 m cells whose lower-left node sits at (10, 20).
HeightField small_grid() {
  return HeightField(5, 4, 0.5, Eigen::Vector2d(10.0, 20.0));
}

TEST(HeightField, RejectsDegenerateGrids) {
  EXPECT_THROW(HeightField(1, 4, 0.1), std::invalid_argument);
  EXPECT_THROW(HeightField(4, 0, 0.1), std::invalid_argument);
  EXPECT_THROW(HeightField(4, 4, 0.0), std::invalid_argument);
  EXPECT_THROW(HeightField(4, 4, -0.1), std::invalid_argument);
  EXPECT_THROW(HeightField(4, 4, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST(HeightField, NodesSitAtOriginPlusIndexTimesCell) {
  const HeightField grid = small_grid();
  EXPECT_EQ(grid.nx(), 5);
  EXPECT_EQ(grid.ny(), 4);
  const Eigen::Vector2d p = grid.node_position(3, 2);
  EXPECT_DOUBLE_EQ(p.x(), 11.5);
  EXPECT_DOUBLE_EQ(p.y(), 21.0);
}

TEST(HeightField, ContainsExactlyTheGridRectangle) {
  const HeightField grid = small_grid(); // x in [10, 12], y in [20, 21.5]
  EXPECT_TRUE(grid.contains(10.0, 20.0));
  EXPECT_TRUE(grid.contains(12.0, 21.5));
  EXPECT_TRUE(grid.contains(11.3, 20.7));
  EXPECT_FALSE(grid.contains(9.999, 20.5));
  EXPECT_FALSE(grid.contains(12.001, 20.5));
  EXPECT_FALSE(grid.contains(11.0, 21.501));
  EXPECT_FALSE(grid.contains(std::numeric_limits<double>::quiet_NaN(), 20.5));
}

TEST(HeightField, HeightIsBilinearBetweenNodes) {
  HeightField grid = small_grid();
  grid.at(1, 1) = 1.0f;
  grid.at(2, 1) = 3.0f;
  grid.at(1, 2) = 5.0f;
  grid.at(2, 2) = 11.0f;
  // Nodes themselves.
  EXPECT_DOUBLE_EQ(grid.height(10.5, 20.5), 1.0);
  EXPECT_DOUBLE_EQ(grid.height(11.0, 21.0), 11.0);
  // Cell centre: the mean of the four corners.
  EXPECT_DOUBLE_EQ(grid.height(10.75, 20.75), (1.0 + 3.0 + 5.0 + 11.0) / 4.0);
  // A quarter along x on the lower edge, then a point inside: hand bilinear weights.
  EXPECT_DOUBLE_EQ(grid.height(10.625, 20.5), 0.75 * 1.0 + 0.25 * 3.0);
  const double fx = 0.2;
  const double fy = 0.6;
  const double expected =
      (1 - fx) * (1 - fy) * 1.0 + fx * (1 - fy) * 3.0 + (1 - fx) * fy * 5.0 + fx * fy * 11.0;
  EXPECT_NEAR(grid.height(10.5 + fx * 0.5, 20.5 + fy * 0.5), expected, 1e-12);
}

TEST(HeightField, PlanesAreReproducedExactlyWithTheirNormal) {
  HeightField grid = small_grid();
  const double a = 0.3;
  const double b = -0.2;
  for (int j = 0; j < grid.ny(); ++j)
    for (int i = 0; i < grid.nx(); ++i) {
      const Eigen::Vector2d p = grid.node_position(i, j);
      grid.at(i, j) = static_cast<float>(a * (p.x() - 10.0) + b * (p.y() - 20.0));
    }
  const Eigen::Vector3d expected_normal = Eigen::Vector3d(-a, -b, 1.0).normalized();
  for (const auto& [x, y] : {std::pair{10.1, 20.2}, {11.77, 21.31}, {11.999, 20.001}}) {
    EXPECT_NEAR(grid.height(x, y), a * (x - 10.0) + b * (y - 20.0), 1e-6);
    EXPECT_NEAR((grid.normal(x, y) - expected_normal).norm(), 0.0, 1e-6);
  }
}

TEST(HeightField, NormalFollowsTheTwistOfASaddlePatch) {
  // z = k * u * v on the cell [10, 10.5] x [20, 20.5] with u, v the offsets from its corner.
  HeightField grid = small_grid();
  grid.at(1, 1) = 2.0f; // z(0.5, 0.5) = k * 0.25 with k = 8
  const double k = 8.0;
  const double u = 0.1;
  const double v = 0.4;
  EXPECT_NEAR(grid.height(10.0 + u, 20.0 + v), k * u * v, 1e-12);
  const Eigen::Vector3d expected = Eigen::Vector3d(-k * v, -k * u, 1.0).normalized();
  EXPECT_NEAR((grid.normal(10.0 + u, 20.0 + v) - expected).norm(), 0.0, 1e-12);
}

TEST(HeightField, ClampsToTheBorderOutsideTheGrid) {
  HeightField grid = small_grid();
  grid.at(0, 0) = 4.0f;
  grid.at(4, 3) = -2.0f;
  EXPECT_DOUBLE_EQ(grid.height(-100.0, -100.0), 4.0);
  EXPECT_DOUBLE_EQ(grid.height(100.0, 100.0), -2.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isfinite(grid.height(nan, nan)));
  EXPECT_TRUE(grid.normal(nan, 20.0).allFinite());
}

TEST(HeightField, DefaultConstructedFieldIsEmptyButSafe) {
  const HeightField empty;
  EXPECT_EQ(empty.nx(), 0);
  EXPECT_FALSE(empty.contains(0.0, 0.0));
  EXPECT_EQ(empty.height(0.0, 0.0), 0.0);
  EXPECT_EQ(empty.normal(0.0, 0.0), Eigen::Vector3d::UnitZ());
}

} // namespace
} // namespace marsokhod::world
