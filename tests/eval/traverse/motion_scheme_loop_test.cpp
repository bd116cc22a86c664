// Tests: the paper's motion scheme driven through the loop by hand-made ground whose answer is
// known: a ring of rocks no path leaves (a full turn, then the operator), and a ramp steeper
// than the inclinometer's threshold but within the zones' slope limit (an emergency stop and a
// turn away from the side that rose).

#include "world/hand_scenes.hpp"

#include "marsokhod/eval/traverse/traverse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace marsokhod::eval {
namespace {

// The course of goal_m = 10: the rover at (-5, 0) facing east, the goal at (5, 0).
TraverseSettings ten_metre_course() {
  TraverseSettings s;
  s.goal_m = 10.0;
  return s;
}

world::Terrain textured(world::HeightField field) {
  return test::terrain_from(std::move(field), test::smooth_albedo);
}

// A 0.6 m wall (twice the 0.30 m step) 0.3 m thick all round the start at 3.5 m: no path of
// 10-12 m or 3-4 m leaves it, so the scheme turns 30 deg eleven times (330 deg) and hands over.
TEST(MotionSchemeLoop, ARingOfRocksEndsInAHandOverAfterAFullTurn) {
  world::HeightField field = test::flat_field(12.0, 0.02);
  const Eigen::Vector2d start(-5.0, 0.0);
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i) {
      const double r = (field.node_position(i, j) - start).norm();
      if (r >= 3.5 && r <= 3.8)
        field.at(i, j) = 0.6f;
    }
  const TraverseResult r = run_traverse(textured(std::move(field)), ten_metre_course());
  EXPECT_EQ(r.outcome, TraverseOutcome::hand_over);
  EXPECT_EQ(r.hand_overs, 1);
  EXPECT_EQ(r.distance_m, 0.0);
  double turned = 0.0;
  for (const TraverseCycle& cycle : r.cycles) {
    EXPECT_FALSE(cycle.found) << "cycle " << cycle.index;
    turned += cycle.turned_deg;
  }
  EXPECT_DOUBLE_EQ(std::abs(turned), 330.0);
  EXPECT_EQ(r.cycles.size(), 13u); // the normal plan, eleven escapes, the hand-over
}

// Beyond 3 m ahead of the start the ground tilts sideways, its left (north) side up, to 22 deg
// over 2 m (z = tan 22 deg * y * twist): the zones allow it (their limit is 25 deg), the
// inclinometer stops the rover once its roll is over 20 deg, which happens between the front
// axle entering the twist (2.25 m) and the rear axle leaving it (5.75 m, read within 0.25 m),
// and the scheme turns 30 deg away from the side that rose: to the right.
TEST(MotionSchemeLoop, ASideSlopeOverTheThresholdStopsTheRoverAndTurnsItAway) {
  world::HeightField field = test::flat_field(12.0, 0.02);
  const double rise = std::tan(22.0 * std::numbers::pi / 180.0);
  const double twist_from = -5.0 + 3.0;
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i) {
      const Eigen::Vector2d p = field.node_position(i, j);
      const double twist = std::clamp((p.x() - twist_from) / 2.0, 0.0, 1.0);
      field.at(i, j) = static_cast<float>(rise * p.y() * twist);
    }
  TraverseSettings s = ten_metre_course();
  s.max_cycles = 2;
  const TraverseResult r = run_traverse(textured(std::move(field)), s);
  ASSERT_GE(r.cycles.size(), 2u);
  const TraverseCycle& first = r.cycles[0];
  ASSERT_TRUE(first.found) << first.reason;
  ASSERT_TRUE(first.emergency_stop) << "drove " << first.driven_m << " m";
  EXPECT_GE(r.emergency_stops, 1); // the escape may climb further into the tilt and stop again
  EXPECT_TRUE(r.unsafe_events.empty()) << r.unsafe_events.front().why;
  EXPECT_GT(first.driven_m, 2.25);
  EXPECT_LE(first.driven_m, 5.75 + 0.25 + 1e-9);
  EXPECT_DOUBLE_EQ(r.cycles[1].turned_deg, -30.0);
  EXPECT_EQ(r.cycles[1].state, nav::MotionState::escape_planning);
}

} // namespace
} // namespace marsokhod::eval
