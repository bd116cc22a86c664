// The paper's motion scheme: states, events and the rover's next step between cycles.
#pragma once

#include <string_view>

namespace marsokhod::nav {

/// Where the rover is in the motion scheme of the paper (section 3).
enum class MotionState {
  normal_planning, ///< looking for a path of the normal range (10-12 m)
  normal_driving,  ///< executing such a path
  escape_planning, ///< after an emergency turn, looking for a short path (3-4 m)
  escape_driving,  ///< executing a short path
  remote_control,  ///< a full turn gave no path: the operator drives
};

/// What happened: the planner's answer, the end of a path, the inclinometers, the operator.
enum class MotionEventKind {
  path_found,
  no_path,
  path_done,            ///< the path was executed to its end
  inclination_exceeded, ///< the rover's inclination went over the threshold
  operator_resume,      ///< the operator hands control back to the rover
};

/// Side of the rover on which the inclination found the obstacle (the side that rose).
enum class Side { left, right };

struct MotionEvent {
  MotionEventKind kind = MotionEventKind::path_found;
  Side obstacle_side = Side::left; ///< for inclination_exceeded only
};

/// What the rover must do next, in order: stop, turn on the spot, then plan, drive or hand
/// over to the operator.
struct MotionAction {
  enum class Then { nothing, plan, drive, hand_over };
  bool stop = false;
  double turn_deg = 0.0; ///< counter-clockwise positive
  Then then = Then::nothing;
  double plan_min_m = 0.0; ///< the destination range to plan for, with Then::plan
  double plan_max_m = 0.0;
};

/// The scheme's parameters (paper, section 3).
struct MotionConfig {
  double normal_min_m = 10.0;
  double normal_max_m = 12.0;
  double escape_min_m = 3.0;
  double escape_max_m = 4.0;
  double turn_step_deg = 30.0;
  /// Which way to turn when normal planning finds no path (no obstacle side is known then).
  Side turn_without_obstacle = Side::left;
};

/// The scheme's memory: its state and the turning done since the last emergency began.
struct MotionStatus {
  MotionState state = MotionState::normal_planning;
  double turned_deg = 0.0; ///< total of this escape's turns, always positive
  double turn_sign = 0.0;  ///< +1 turning left, -1 turning right, 0 outside an escape
  friend bool operator==(const MotionStatus&, const MotionStatus&) = default;
};

/// One transition: the next status and what to do; `ignored` is true when the event means
/// nothing in that state (the status is unchanged then and the action does nothing).
struct MotionStep {
  MotionStatus status;
  MotionAction action;
  bool ignored = false;
};

/// The scheme as a pure function: no clock, no hidden state. Throws std::invalid_argument for
/// a configuration whose ranges or turn step make no sense.
MotionStep next_motion_step(const MotionStatus& status, const MotionEvent& event,
                            const MotionConfig& config = {});

/// The action that starts the scheme: plan a path of the normal range.
MotionAction initial_motion_action(const MotionConfig& config = {});

std::string_view to_string(MotionState state);

} // namespace marsokhod::nav
