// Tests: the hazard memory keeps steps and slopes where the odometry put them and gives them
// back in the rover's frame, by hand geometry.

#include "marsokhod/nav/cycle/hazard_memory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace marsokhod::nav {
namespace {

// A one-row view of `points` (forward, left), each pixel in the given zone.
struct View {
  TerrainPoints terrain;
  ZoneMap zones;
};

View view_of(const std::vector<std::pair<GroundPoint, Zone>>& points) {
  const int n = static_cast<int>(points.size());
  View v{{imaging::Image<float>(n, 1), imaging::Image<float>(n, 1), imaging::Image<float>(n, 1),
          imaging::Image<float>(n, 1), static_cast<std::uint64_t>(n)},
         {imaging::Image<std::uint8_t>(n, 1, 1, 0), {}}};
  for (int x = 0; x < n; ++x) {
    const auto& [p, zone] = points[static_cast<std::size_t>(x)];
    v.terrain.forward(x, 0) = static_cast<float>(p.x);
    v.terrain.left(x, 0) = static_cast<float>(p.y);
    v.terrain.elevation(x, 0) = 0.0f;
    v.terrain.range(x, 0) = static_cast<float>(std::hypot(p.x, p.y));
    v.zones.zone(x, 0) = static_cast<std::uint8_t>(zone);
  }
  return v;
}

constexpr double kQuarterTurn = 0.5 * std::numbers::pi;

// A step 3 m ahead of a rover at the origin facing +x sits at (3, 0). From (1, 0) facing +x it
// is 2 m ahead; from the origin facing +y (a quarter turn left) it is 3 m to the right.
TEST(HazardMemory, GivesAPointBackInTheFrameOfTheRoverNow) {
  HazardMemory memory;
  const View v = view_of({{{3.0, 0.0}, Zone::step}});
  memory.remember(v.terrain, v.zones, {0.0, 0.0, 0.0});
  const std::vector<GroundPoint> moved = memory.recall({1.0, 0.0, 0.0}, 10.0);
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_NEAR(moved[0].x, 2.0, 1e-9);
  EXPECT_NEAR(moved[0].y, 0.0, 1e-9);
  const std::vector<GroundPoint> turned = memory.recall({0.0, 0.0, kQuarterTurn}, 10.0);
  ASSERT_EQ(turned.size(), 1u);
  EXPECT_NEAR(turned[0].x, 0.0, 1e-9);
  EXPECT_NEAR(turned[0].y, -3.0, 1e-9);
}

// Seen by a rover at (2, 1) facing +y, a slope 1 m ahead and 0.5 m left lies at (1.5, 2).
TEST(HazardMemory, PlacesWhatTheRoverSawFromItsOwnPose) {
  HazardMemory memory;
  const View v = view_of({{{1.0, 0.5}, Zone::slope}});
  memory.remember(v.terrain, v.zones, {2.0, 1.0, kQuarterTurn});
  const std::vector<GroundPoint> back = memory.recall({0.0, 0.0, 0.0}, 10.0);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_NEAR(back[0].x, 1.5, 1e-9);
  EXPECT_NEAR(back[0].y, 2.0, 1e-9);
}

TEST(HazardMemory, KeepsStepsAndSlopesOnlyOncePerCell) {
  HazardMemory memory(2, 0.05);
  const View v = view_of({{{3.0, 0.0}, Zone::step},
                          {{3.01, 0.01}, Zone::step}, // the same 5 cm cell
                          {{4.0, 0.0}, Zone::margin},
                          {{5.0, 0.0}, Zone::unknown},
                          {{6.0, 0.0}, Zone::traversable},
                          {{7.0, 0.0}, Zone::slope}});
  memory.remember(v.terrain, v.zones, {0.0, 0.0, 0.0});
  const std::vector<GroundPoint> back = memory.recall({0.0, 0.0, 0.0}, 10.0);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_NEAR(back[0].x, 3.0, 1e-9);
  EXPECT_NEAR(back[1].x, 7.0, 1e-9);
}

TEST(HazardMemory, ForgetsCyclesBeyondItsCountAndPointsBeyondTheRadius) {
  HazardMemory memory(2);
  for (const double ahead : {1.0, 2.0, 3.0}) {
    const View v = view_of({{{ahead, 0.0}, Zone::step}});
    memory.remember(v.terrain, v.zones, {0.0, 0.0, 0.0});
  }
  const std::vector<GroundPoint> kept = memory.recall({0.0, 0.0, 0.0}, 10.0);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_NEAR(kept[0].x, 2.0, 1e-9);
  EXPECT_NEAR(kept[1].x, 3.0, 1e-9);
  const std::vector<GroundPoint> near = memory.recall({0.0, 0.0, 0.0}, 2.5);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_NEAR(near[0].x, 2.0, 1e-9);
}

TEST(HazardMemory, RefusesMeaninglessSettings) {
  EXPECT_THROW(HazardMemory(0), std::invalid_argument);
  EXPECT_THROW(HazardMemory(2, 0.0), std::invalid_argument);
  EXPECT_THROW(HazardMemory(2, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
