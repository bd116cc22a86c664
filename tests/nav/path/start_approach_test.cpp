// Tests: the pixels the rover crosses on its way to the start of a path.

#include "nav/terrain_grid.hpp"

#include "marsokhod/nav/path/start_approach.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace marsokhod::nav {
namespace {

using testing::grid_forward;
using testing::grid_left;
using testing::grid_terrain;
using testing::GridSpec;
using testing::long_grid;

TEST(StartApproach, FollowsTheLineFromTheRoverCentreToTheStart) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  // The start 7.0 m ahead and 0.5 m to the right: row 107, column 30.
  const PixelPoint start{30, 107};
  ASSERT_NEAR(grid_forward(g, start.y), 7.0, 1e-9);
  ASSERT_NEAR(grid_left(g, start.x), -0.5, 1e-9);
  const auto approach = start_approach(t, start);
  // One pixel in each of rows 108..207, nearest first from the start.
  ASSERT_EQ(approach.size(), 100U);
  for (std::size_t i = 0; i < approach.size(); ++i) {
    const PixelPoint p = approach[i];
    EXPECT_EQ(p.y, start.y + 1 + static_cast<int>(i));
    // The line passes -0.5 * f / 7 to the left at f metres ahead; the grid's nearest column
    // lies within half a column of it.
    const double line = -0.5 * grid_forward(g, p.y) / 7.0;
    EXPECT_LE(std::abs(grid_left(g, p.x) - line), 0.025 + 1e-9) << p.x << "," << p.y;
  }
  // 2.0 m ahead the line is 0.143 m to the right: column 23 (0.15 m).
  EXPECT_EQ(approach.back(), (PixelPoint{23, 207}));
}

TEST(StartApproach, LeavesOutRowsWhereTheLineMeetsNoKnownPoint) {
  const GridSpec g = long_grid();
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  for (int x = 0; x < g.width; ++x)
    t.elevation(x, 150) = std::numeric_limits<float>::infinity(); // a row with no point
  t.elevation(20, 160) = std::numeric_limits<float>::infinity();  // the line's own pixel
  // Row 160's nearest known points, columns 19 and 21, lie 0.05 m from the line: just outside
  // the default tolerance (the grid's 0.05 m in float is a hair more), inside 0.06 m.
  const auto approach = start_approach(t, PixelPoint{20, 140});
  EXPECT_EQ(approach.size(), 65U); // rows 141..207 but 150 and 160
  for (const PixelPoint& p : approach) {
    EXPECT_NE(p.y, 150);
    EXPECT_NE(p.y, 160);
    EXPECT_EQ(p.x, 20) << p.y;
  }
  const auto wider = start_approach(t, PixelPoint{20, 140}, 0.06);
  ASSERT_EQ(wider.size(), 66U);
  EXPECT_EQ(wider[18], (PixelPoint{19, 160})); // the leftmost of the two
  // A start with no known point of its own has no line to follow.
  EXPECT_TRUE(start_approach(t, PixelPoint{20, 150}).empty());
}

} // namespace
} // namespace marsokhod::nav
