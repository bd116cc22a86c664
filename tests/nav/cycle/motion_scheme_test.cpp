// Tests: the motion scheme's transitions, turn steps and configuration checks.

#include "marsokhod/nav/cycle/motion_scheme.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

// The motion scheme of the paper (section 3): normal paths of 10-12 m; on an emergency stop,
// turn one step away from the obstacle and look for a 3-4 m path, turning one step further
// each time none is found; after a full turn hand over to the operator; after any path is
// executed start again with normal paths.

namespace marsokhod::nav {
namespace {

using Kind = MotionEventKind;
using State = MotionState;
using Then = MotionAction::Then;

struct Row {
  std::string name;
  MotionStatus from;
  MotionEvent event;
  MotionStatus to;
  bool stop;
  double turn_deg;
  Then then;
  double plan_min_m;
  double plan_max_m;
  bool ignored;
};

const MotionStatus kNormalPlanning{State::normal_planning, 0.0, 0.0};
const MotionStatus kNormalDriving{State::normal_driving, 0.0, 0.0};

// With the default 30 deg step. Turning left is +1, right -1.
const std::vector<Row> kTable = {
    {"normal plan found: drive it",
     kNormalPlanning,
     {Kind::path_found},
     kNormalDriving,
     false,
     0.0,
     Then::drive,
     0.0,
     0.0,
     false},
    {"normal plan failed: turn one step (left) and look for a short path",
     kNormalPlanning,
     {Kind::no_path},
     {State::escape_planning, 30.0, 1.0},
     true,
     30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"normal drive done: plan again",
     kNormalDriving,
     {Kind::path_done},
     kNormalPlanning,
     false,
     0.0,
     Then::plan,
     10.0,
     12.0,
     false},
    {"tilt while driving, obstacle on the left: stop, turn right",
     kNormalDriving,
     {Kind::inclination_exceeded, Side::left},
     {State::escape_planning, 30.0, -1.0},
     true,
     -30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"tilt while driving, obstacle on the right: stop, turn left",
     kNormalDriving,
     {Kind::inclination_exceeded, Side::right},
     {State::escape_planning, 30.0, 1.0},
     true,
     30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"tilt while planning normally: escape away from it",
     kNormalPlanning,
     {Kind::inclination_exceeded, Side::right},
     {State::escape_planning, 30.0, 1.0},
     true,
     30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"short path found: drive it",
     {State::escape_planning, 60.0, -1.0},
     {Kind::path_found},
     {State::escape_driving, 60.0, -1.0},
     false,
     0.0,
     Then::drive,
     0.0,
     0.0,
     false},
    {"no short path: turn one more step the same way",
     {State::escape_planning, 60.0, -1.0},
     {Kind::no_path},
     {State::escape_planning, 90.0, -1.0},
     false,
     -30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"tilt while turning: one more step the same way",
     {State::escape_planning, 60.0, -1.0},
     {Kind::inclination_exceeded, Side::right},
     {State::escape_planning, 90.0, -1.0},
     true,
     -30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"no short path at 330 deg: a full turn failed, remote control",
     {State::escape_planning, 330.0, 1.0},
     {Kind::no_path},
     {State::remote_control, 330.0, 1.0},
     false,
     0.0,
     Then::hand_over,
     0.0,
     0.0,
     false},
    {"short path executed: back to normal paths",
     {State::escape_driving, 90.0, 1.0},
     {Kind::path_done},
     kNormalPlanning,
     false,
     0.0,
     Then::plan,
     10.0,
     12.0,
     false},
    {"tilt on the short path: a new escape from one step",
     {State::escape_driving, 270.0, 1.0},
     {Kind::inclination_exceeded, Side::left},
     {State::escape_planning, 30.0, -1.0},
     true,
     -30.0,
     Then::plan,
     3.0,
     4.0,
     false},
    {"operator resumes: normal paths",
     {State::remote_control, 330.0, 1.0},
     {Kind::operator_resume},
     kNormalPlanning,
     false,
     0.0,
     Then::plan,
     10.0,
     12.0,
     false},
};

TEST(MotionScheme, EveryTransitionOfThePapersScheme) {
  for (const Row& row : kTable) {
    const MotionStep step = next_motion_step(row.from, row.event);
    EXPECT_EQ(step.status, row.to) << row.name;
    EXPECT_EQ(step.action.stop, row.stop) << row.name;
    EXPECT_DOUBLE_EQ(step.action.turn_deg, row.turn_deg) << row.name;
    EXPECT_EQ(step.action.then, row.then) << row.name;
    EXPECT_DOUBLE_EQ(step.action.plan_min_m, row.plan_min_m) << row.name;
    EXPECT_DOUBLE_EQ(step.action.plan_max_m, row.plan_max_m) << row.name;
    EXPECT_EQ(step.ignored, row.ignored) << row.name;
  }
}

TEST(MotionScheme, EventsThatMeanNothingInAStateAreIgnored) {
  const std::vector<std::pair<MotionStatus, Kind>> meaningless = {
      {kNormalPlanning, Kind::path_done},
      {kNormalPlanning, Kind::operator_resume},
      {kNormalDriving, Kind::path_found},
      {kNormalDriving, Kind::no_path},
      {kNormalDriving, Kind::operator_resume},
      {{State::escape_planning, 30.0, 1.0}, Kind::path_done},
      {{State::escape_driving, 30.0, 1.0}, Kind::no_path},
      {{State::remote_control, 330.0, 1.0}, Kind::path_found},
      {{State::remote_control, 330.0, 1.0}, Kind::inclination_exceeded},
  };
  for (const auto& [status, kind] : meaningless) {
    const MotionStep step = next_motion_step(status, {kind});
    EXPECT_TRUE(step.ignored) << to_string(status.state);
    EXPECT_EQ(step.status, status) << to_string(status.state);
    EXPECT_EQ(step.action.then, Then::nothing);
  }
}

TEST(MotionScheme, AFullTurnWithoutAPathTakesElevenStepsOfThirtyDegrees) {
  MotionStatus status = kNormalDriving;
  MotionStep step = next_motion_step(status, {Kind::inclination_exceeded, Side::right});
  double turned = step.action.turn_deg;
  int plans = 1;
  while (step.action.then == Then::plan) {
    step = next_motion_step(step.status, {Kind::no_path});
    turned += step.action.turn_deg;
    plans += step.action.then == Then::plan ? 1 : 0;
  }
  EXPECT_EQ(step.action.then, Then::hand_over);
  EXPECT_EQ(step.status.state, State::remote_control);
  EXPECT_EQ(plans, 11); // headings 30, 60, ..., 330 deg were tried
  EXPECT_DOUBLE_EQ(turned, 330.0);
}

TEST(MotionScheme, TheStepAndRangesAreConfigurable) {
  MotionConfig config;
  config.turn_step_deg = 90.0;
  config.escape_min_m = 2.0;
  config.escape_max_m = 3.0;
  const MotionStep step = next_motion_step(kNormalPlanning, {Kind::no_path}, config);
  EXPECT_DOUBLE_EQ(step.action.turn_deg, 90.0);
  EXPECT_DOUBLE_EQ(step.action.plan_min_m, 2.0);
  const MotionStep last =
      next_motion_step({State::escape_planning, 270.0, 1.0}, {Kind::no_path}, config);
  EXPECT_EQ(last.status.state, State::remote_control);
  EXPECT_EQ(initial_motion_action(config).then, Then::plan);
  EXPECT_DOUBLE_EQ(initial_motion_action(config).plan_min_m, 10.0);
}

TEST(MotionScheme, RejectsConfigurationsThatMakeNoSense) {
  MotionConfig no_step;
  no_step.turn_step_deg = 0.0;
  EXPECT_THROW(next_motion_step(kNormalPlanning, {Kind::no_path}, no_step), std::invalid_argument);
  MotionConfig reversed;
  reversed.escape_min_m = 5.0;
  reversed.escape_max_m = 4.0;
  EXPECT_THROW(next_motion_step(kNormalPlanning, {Kind::no_path}, reversed), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
