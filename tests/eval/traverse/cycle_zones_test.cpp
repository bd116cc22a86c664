// Tests: a cycle's zones placed on the ground for the map, by hand geometry.

#include "marsokhod/eval/traverse/cycle_zones.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace marsokhod::eval {
namespace {

// A one-row navigation result seeing `points` (forward, left) in the given zones.
nav::NavigationResult seeing(const std::vector<std::pair<Eigen::Vector2d, nav::Zone>>& points) {
  const int n = static_cast<int>(points.size());
  nav::NavigationResult r;
  r.terrain = {imaging::Image<float>(n, 1), imaging::Image<float>(n, 1),
               imaging::Image<float>(n, 1), imaging::Image<float>(n, 1),
               static_cast<std::uint64_t>(n)};
  r.zones.zone = imaging::Image<std::uint8_t>(n, 1, 1, 0);
  for (int x = 0; x < n; ++x) {
    const auto& [p, zone] = points[static_cast<std::size_t>(x)];
    r.terrain.forward(x, 0) = static_cast<float>(p.x());
    r.terrain.left(x, 0) = static_cast<float>(p.y());
    r.terrain.elevation(x, 0) = 0.0f;
    r.terrain.range(x, 0) = static_cast<float>(p.norm());
    r.zones.zone(x, 0) = static_cast<std::uint8_t>(zone);
  }
  return r;
}

// The rover at (10, 5) facing north: 2 m ahead is (10, 7), 1 m to its left (9, 5).
TEST(CycleZones, PlacesSeenAndProhibitedGroundFromTheRoversPose) {
  world::RoverPlacement placement;
  placement.level_to_world = Eigen::Translation3d(10.0, 5.0, 0.0) *
                             Eigen::AngleAxisd(0.5 * std::numbers::pi, Eigen::Vector3d::UnitZ());
  const nav::NavigationResult r = seeing({{{2.0, 0.0}, nav::Zone::traversable},
                                          {{0.0, 1.0}, nav::Zone::step},
                                          {{3.0, 0.0}, nav::Zone::margin},
                                          {{4.0, 0.0}, nav::Zone::unknown},
                                          {{5.0, -1.0}, nav::Zone::slope}});
  TraverseCycle cycle;
  book_zones(placement, r, 0.10, cycle);
  ASSERT_EQ(cycle.seen.size(), 2u);
  EXPECT_NEAR(cycle.seen[0].x(), 10.0, 1e-9);
  EXPECT_NEAR(cycle.seen[0].y(), 7.0, 1e-9);
  EXPECT_NEAR(cycle.seen[1].y(), 8.0, 1e-9);
  ASSERT_EQ(cycle.prohibited.size(), 2u);
  EXPECT_NEAR(cycle.prohibited[0].x(), 9.0, 1e-9); // 1 m left of a rover facing north is west
  EXPECT_NEAR(cycle.prohibited[0].y(), 5.0, 1e-9);
  EXPECT_NEAR(cycle.prohibited[1].x(), 11.0, 1e-9); // 5 m ahead, 1 m right
  EXPECT_NEAR(cycle.prohibited[1].y(), 10.0, 1e-9);
}

TEST(CycleZones, ACellBothSeenAndProhibitedIsProhibitedOnce) {
  const nav::NavigationResult r = seeing({{{2.00, 0.0}, nav::Zone::traversable},
                                          {{2.01, 0.0}, nav::Zone::step},
                                          {{2.02, 0.0}, nav::Zone::step}});
  TraverseCycle cycle;
  book_zones(world::RoverPlacement{}, r, 0.10, cycle);
  EXPECT_TRUE(cycle.seen.empty());
  ASSERT_EQ(cycle.prohibited.size(), 1u);
  EXPECT_NEAR(cycle.prohibited[0].x(), 2.0, 1e-9);
}

} // namespace
} // namespace marsokhod::eval
