// Tests: whole traverses on generated sites, judged by geometry (the goal's distance bounds the
// drive) and by determinism; bad settings.

#include "marsokhod/eval/traverse/traverse.hpp"
#include "marsokhod/eval/traverse/traverse_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace marsokhod::eval {
namespace {

TraverseSettings short_bare_course() {
  TraverseSettings s;
  s.seed = 4;
  s.rocks = 0.0;
  s.slope_deg = 0.0;
  s.goal_m = 20.0;
  return s;
}

std::string without_host(nlohmann::ordered_json doc) {
  doc.erase("host");
  return doc.dump();
}

// Within 1.5 m of a goal 20 m away is at least 18.5 m of driving; on ground without rocks the
// rover should not wander far from the straight line.
TEST(Traverse, RockFreeCourseReachesTheGoal) {
  const TraverseResult r = run_traverse(short_bare_course());
  ASSERT_EQ(r.outcome, TraverseOutcome::success) << traverse_json(r).dump(2);
  EXPECT_LE(r.goal_left_m, 1.5);
  EXPECT_GE(r.distance_m, 18.5 - 1e-9);
  EXPECT_GT(r.path_efficiency(), 0.85);
  EXPECT_TRUE(r.unsafe_events.empty());
  EXPECT_GE(r.cycles.size(), 2u); // a normal path is at most 12 m
}

// Normal paths of 4-6 m: each normal cycle's destination lies 4 to 6 m from where the rover
// stood (the goal, 20 m away, is nearer than 6 m only in the last cycle), so a 20 m course
// takes at least four cycles where 10-12 m paths take two.
TEST(Traverse, TheNormalPathBandSetsHowFarEachCyclePlans) {
  TraverseSettings s = short_bare_course();
  s.motion.normal_min_m = 4.0;
  s.motion.normal_max_m = 6.0;
  const TraverseResult r = run_traverse(s);
  ASSERT_EQ(r.outcome, TraverseOutcome::success) << traverse_json(r).dump(2);
  EXPECT_GE(r.cycles.size(), 4u);
  for (std::size_t i = 0; i + 1 < r.cycles.size(); ++i) {
    const TraverseCycle& c = r.cycles[i];
    if (c.state != nav::MotionState::normal_planning || !c.found)
      continue;
    const double reach = (c.planned.back() - c.planned.front()).norm();
    EXPECT_GE(reach, 4.0 - 0.3) << "cycle " << i; // the path's destination pixel, 5 cm cells
    EXPECT_LE(reach, 6.0 + 0.3) << "cycle " << i;
  }
}

TEST(Traverse, SameSettingsGiveTheSameTraverse) {
  TraverseSettings s = short_bare_course();
  s.rocks = 0.10;
  const TraverseResult a = run_traverse(s);
  const TraverseResult b = run_traverse(s);
  EXPECT_EQ(without_host(traverse_json(a)), without_host(traverse_json(b)));
  ASSERT_EQ(a.cycles.size(), b.cycles.size());
  for (std::size_t i = 0; i < a.cycles.size(); ++i) {
    nlohmann::ordered_json ca = cycle_json(a.cycles[i]);
    nlohmann::ordered_json cb = cycle_json(b.cycles[i]);
    EXPECT_EQ(without_host(ca), without_host(cb));
  }
}

TEST(Traverse, CycleLimitEndsInTimeout) {
  TraverseSettings s = short_bare_course();
  s.goal_m = 60.0;
  s.max_cycles = 1;
  const TraverseResult r = run_traverse(s);
  EXPECT_EQ(r.outcome, TraverseOutcome::timeout);
  EXPECT_EQ(r.cycles.size(), 1u);
}

// Natively the navigation takes no mission time; on the onboard computer each cycle's emulated
// time is added to the driving.
TEST(Traverse, EmulatedCyclesCountAsMissionTime) {
  TraverseSettings s = short_bare_course();
  s.goal_m = 10.0;
  const TraverseResult native = run_traverse(s);
  EXPECT_EQ(native.compute_seconds, 0.0);
  EXPECT_EQ(native.mission_seconds(), native.driving_seconds);

  s.platform = "onboard";
  s.image_px = 128;
  const TraverseResult onboard = run_traverse(s);
  ASSERT_FALSE(onboard.cycles.empty());
  double sum = 0.0;
  for (const TraverseCycle& cycle : onboard.cycles) {
    EXPECT_GT(cycle.compute_seconds, 1.0) << "cycle " << cycle.index; // seconds, not ms, on a T805
    sum += cycle.compute_seconds;
  }
  EXPECT_DOUBLE_EQ(onboard.compute_seconds, sum);
  EXPECT_DOUBLE_EQ(onboard.mission_seconds(), onboard.driving_seconds + sum);

  // The emulated cycle runs the same navigation: at the same image size the rover plans and
  // drives exactly as it does natively.
  s.platform = "native";
  const TraverseResult same_size = run_traverse(s);
  ASSERT_EQ(same_size.cycles.size(), onboard.cycles.size());
  for (std::size_t i = 0; i < onboard.cycles.size(); ++i) {
    EXPECT_EQ(same_size.cycles[i].planned, onboard.cycles[i].planned) << "cycle " << i;
    EXPECT_EQ(same_size.cycles[i].track, onboard.cycles[i].track) << "cycle " << i;
  }
  EXPECT_EQ(same_size.outcome, onboard.outcome);
}

// With slip the ground gives each drive (1 - s) of its commanded lengths: the first path's
// driven length is the planned length times that share (to the 5 cm pose spacing), and the
// odometry, counting wheel turns, believes the rover went the whole way.
TEST(Traverse, SlipShortensEachDriveAndTheOdometryOvershoots) {
  TraverseSettings s = short_bare_course();
  s.slip = 0.3;
  s.max_cycles = 1;
  const TraverseResult r = run_traverse(s);
  ASSERT_EQ(r.cycles.size(), 1u);
  const TraverseCycle& c = r.cycles[0];
  ASSERT_TRUE(c.found) << c.reason;
  EXPECT_GE(c.slip, 0.15);
  EXPECT_LT(c.slip, 0.45);
  EXPECT_NEAR(c.driven_m, c.planned_m * (1.0 - c.slip), 0.06);
  const double moved = std::hypot(r.end.x - r.start.x, r.end.y - r.start.y);
  EXPECT_NEAR(r.odometry_error_m(), moved * c.slip / (1.0 - c.slip), 1e-6);
}

// The rover steers by its odometry; the judge sees the truth. At 20 % slip a 20 m course is
// still finished, with the odometry some way off.
TEST(Traverse, SlippingRoverStillReachesTheGoal) {
  TraverseSettings s = short_bare_course();
  s.slip = 0.2;
  const TraverseResult r = run_traverse(s);
  ASSERT_EQ(r.outcome, TraverseOutcome::success) << traverse_json(r).dump(2);
  EXPECT_GT(r.odometry_error_m(), 0.5);
}

std::string refusal(const TraverseSettings& s) {
  try {
    validate(s);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Traverse, BadSettingsAreRefusedNamingTheSetting) {
  TraverseSettings s;
  s.rocks = 0.7;
  EXPECT_NE(refusal(s).find("rocks"), std::string::npos);
  s = {};
  s.slope_deg = 16.0;
  EXPECT_NE(refusal(s).find("slope"), std::string::npos);
  s = {};
  s.goal_m = 2.0;
  EXPECT_NE(refusal(s).find("goal"), std::string::npos);
  s = {};
  s.emergency_tilt_deg = 30.0;
  EXPECT_NE(refusal(s).find("emergency tilt"), std::string::npos);
  s = {};
  s.light = "moonlight";
  EXPECT_NE(refusal(s), "accepted");
  s = {};
  s.platform = "cray";
  EXPECT_NE(refusal(s).find("platform 'cray'"), std::string::npos);
  s = {};
  s.slip = 0.51;
  EXPECT_NE(refusal(s).find("slip"), std::string::npos);
}

} // namespace
} // namespace marsokhod::eval
