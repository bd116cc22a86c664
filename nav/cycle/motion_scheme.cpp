// The motion scheme's transitions: planning, driving, escape turns and remote control.

#include "marsokhod/nav/cycle/motion_scheme.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

using Then = MotionAction::Then;

void validate(const MotionConfig& c) {
  const bool ranges_ok = std::isfinite(c.normal_min_m) && std::isfinite(c.normal_max_m) &&
                         std::isfinite(c.escape_min_m) && std::isfinite(c.escape_max_m) &&
                         c.normal_min_m > 0.0 && c.normal_max_m >= c.normal_min_m &&
                         c.escape_min_m > 0.0 && c.escape_max_m >= c.escape_min_m;
  if (!ranges_ok)
    throw std::invalid_argument(
        fmt::format("motion scheme: path ranges {}-{} m and {}-{} m must be positive and ordered",
                    c.normal_min_m, c.normal_max_m, c.escape_min_m, c.escape_max_m));
  if (!std::isfinite(c.turn_step_deg) || c.turn_step_deg <= 0.0 || c.turn_step_deg > 180.0)
    throw std::invalid_argument(
        fmt::format("motion scheme: turn step {} deg must be within (0, 180]", c.turn_step_deg));
}

double sign_towards(Side side) {
  return side == Side::left ? 1.0 : -1.0;
}

// Turning away from an obstacle on the left means turning right (clockwise).
double sign_away_from(Side side) {
  return -sign_towards(side);
}

MotionStep plan_normal(const MotionConfig& c) {
  return {{MotionState::normal_planning, 0.0, 0.0},
          {false, 0.0, Then::plan, c.normal_min_m, c.normal_max_m},
          false};
}

MotionStep drive(MotionStatus status, MotionState driving) {
  status.state = driving;
  return {status, {false, 0.0, Then::drive, 0.0, 0.0}, false};
}

// One more turn step in the escape's direction, or the operator after a full turn.
MotionStep turn_further(const MotionStatus& status, bool stop, const MotionConfig& c) {
  const double turned = status.turned_deg + c.turn_step_deg;
  // The turn that would complete the circle would face the blocked heading again.
  if (turned >= 360.0 - 1e-9)
    return {{MotionState::remote_control, status.turned_deg, status.turn_sign},
            {stop, 0.0, Then::hand_over, 0.0, 0.0},
            false};
  return {{MotionState::escape_planning, turned, status.turn_sign},
          {stop, status.turn_sign * c.turn_step_deg, Then::plan, c.escape_min_m, c.escape_max_m},
          false};
}

// A new emergency: stop, then the first turn step away from the obstacle.
MotionStep begin_escape(double sign, const MotionConfig& c) {
  return turn_further({MotionState::escape_planning, 0.0, sign}, true, c);
}

MotionStep ignore(const MotionStatus& status) {
  return {status, {}, true};
}

} // namespace

MotionAction initial_motion_action(const MotionConfig& config) {
  return plan_normal(config).action;
}

MotionStep next_motion_step(const MotionStatus& status, const MotionEvent& event,
                            const MotionConfig& c) {
  validate(c);
  const MotionEventKind kind = event.kind;
  switch (status.state) {
  case MotionState::normal_planning:
    if (kind == MotionEventKind::path_found)
      return drive(status, MotionState::normal_driving);
    if (kind == MotionEventKind::no_path)
      return begin_escape(sign_towards(c.turn_without_obstacle), c);
    if (kind == MotionEventKind::inclination_exceeded)
      return begin_escape(sign_away_from(event.obstacle_side), c);
    return ignore(status);
  case MotionState::escape_planning:
    if (kind == MotionEventKind::path_found)
      return drive(status, MotionState::escape_driving);
    // Standing still and turning: a tilt continues the same escape rather than restarting it,
    // so a full turn still ends in the operator's hands.
    if (kind == MotionEventKind::no_path || kind == MotionEventKind::inclination_exceeded)
      return turn_further(status, kind == MotionEventKind::inclination_exceeded, c);
    return ignore(status);
  case MotionState::normal_driving:
  case MotionState::escape_driving:
    if (kind == MotionEventKind::path_done)
      return plan_normal(c);
    if (kind == MotionEventKind::inclination_exceeded)
      return begin_escape(sign_away_from(event.obstacle_side), c);
    return ignore(status);
  case MotionState::remote_control:
    if (kind == MotionEventKind::operator_resume)
      return plan_normal(c);
    return ignore(status);
  }
  return ignore(status);
}

std::string_view to_string(MotionState state) {
  switch (state) {
  case MotionState::normal_planning:
    return "normal_planning";
  case MotionState::normal_driving:
    return "normal_driving";
  case MotionState::escape_planning:
    return "escape_planning";
  case MotionState::escape_driving:
    return "escape_driving";
  case MotionState::remote_control:
    return "remote_control";
  }
  return "invalid";
}

} // namespace marsokhod::nav
