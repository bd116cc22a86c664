// A closed-loop traverse: the rover drives a course cycle after cycle with the paper's motion
// scheme, judged on the true ground.
#pragma once

#include "marsokhod/eval/traverse/traverse_faults.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/cycle/motion_scheme.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/world/scene/rover_placement.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// One course: the site, the light, the rover and the limits its drive is watched against
/// (docs/traverse.md).
struct TraverseSettings {
  std::uint64_t seed = 1;
  double rocks = 0.10;    ///< Golombek-Rapp cumulative fractional area k
  double slope_deg = 2.0; ///< regional slope of the site
  std::string light = "high-sun";
  /// Where each cycle's navigation runs: "native" (no mission time), or an emulated platform
  /// ("pc-card", "onboard") whose emulated cycle time counts as mission time.
  std::string platform = "native";
  double goal_m = 80.0; ///< straight-line distance from the start to the goal
  /// A campaign file (docs/faults.md) whose fault mix strikes the emulated computer once a
  /// course (eval::TraverseFaults); its platform must be `platform`. Empty: no faults.
  std::string faults_file;
  /// How far along each planned path the rover drives before the next cycle looks again; 0:
  /// to the path's end, as the paper's scheme does.
  double drive_m = 0.0;
  /// Cycles whose steps and slopes the rover remembers (nav::HazardMemory) to check the ground
  /// its next drives begin on, below the cameras' view; 0 keeps nothing between cycles, as the
  /// paper's navigation (docs/traverse.md: remembering did not make courses safer).
  int hazard_memory_cycles = 0;
  /// The motion scheme's normal paths (the paper's 10-12 m) and its escapes.
  nav::MotionConfig motion;
  /// The zones' step window, m (nav::ZoneOptions::step_baseline_m).
  double step_baseline_m = nav::ZoneOptions{}.step_baseline_m;
  /// The footprint check's grid of seen ground, m (nav::FootprintCheckOptions::unseen_cell_m);
  /// 0 lets the footprint cross unseen ground.
  double unseen_cell_m = 0.0;
  /// Mean wheel slip, 0..0.5: the rover steers by dead-reckoned odometry (eval::Odometry) whose
  /// error grows with it; 0 is exact odometry.
  double slip = 0.0;
  int image_px = 256; ///< the stereo pair's width and height
  double goal_tolerance_m = 1.5;
  /// The inclinometer's emergency threshold (the paper: "higher than the threshold"; the value
  /// is not given): below the chassis limit so that the rover stops before it tips.
  double emergency_tilt_deg = 20.0;
  /// A tilt over this is a safety violation: the slope limit of the chassis
  /// (world::LocomotionLimits::max_slope_deg).
  double tilt_limit_deg = 25.0;
  /// The inclinometer is read this often while driving (ENav's 25 cm along the path).
  double read_every_m = 0.25;
  /// Ground speed while driving and turning rate on the spot, for mission time.
  double drive_speed_m_s = 0.10;
  double turn_rate_deg_s = 5.0;
  /// 0: four cycles per ten metres of the course, plus twenty.
  int max_cycles = 0;
  imaging::Chassis chassis;
};

/// Throws std::invalid_argument naming the first setting out of range.
void validate(const TraverseSettings& settings);

/// How a traverse ended.
enum class TraverseOutcome { success, hand_over, unsafe, timeout };
std::string_view to_string(TraverseOutcome outcome);

/// A safety violation on the true ground: where, and why.
struct UnsafeEvent {
  double x_m = 0.0; ///< world frame
  double y_m = 0.0;
  std::string why;
};

/// One cycle of the loop: where it began, what was planned, what was driven, what happened.
struct TraverseCycle {
  int index = 0;
  world::RoverPose start;
  nav::MotionState state = nav::MotionState::normal_planning;
  double turned_deg = 0.0; ///< turn on the spot before planning (an escape step)
  bool found = false;
  std::string reason;                   ///< why no path, when none
  double planned_m = 0.0;               ///< ground length of the planned drive
  double driven_m = 0.0;                ///< ground driven before the drive ended or stopped
  std::vector<Eigen::Vector2d> planned; ///< the planned polyline, world frame
  std::vector<Eigen::Vector2d> track;   ///< the driven centre line, world frame
  /// The ground the cycle's zones judged, one point per map cell (kTraverseMapCellM), world
  /// frame: free (traversable or margin) and prohibited (steps and slopes). For the map; not
  /// written to cycles.jsonl.
  std::vector<Eigen::Vector2d> seen;
  std::vector<Eigen::Vector2d> prohibited;
  bool emergency_stop = false;
  /// Where the rover believed it began (dead-reckoned odometry) and the slip of its path drive.
  world::RoverPose estimate;
  double slip = 0.0;
  double host_seconds = 0.0;    ///< this machine's time for the navigation cycle (not mission time)
  double compute_seconds = 0.0; ///< the emulated cycle's time (0 natively)
  std::vector<std::string> events;
};

/// The whole traverse.
struct TraverseResult {
  TraverseSettings settings;
  TraverseOutcome outcome = TraverseOutcome::timeout;
  world::RoverPose start;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
  world::RoverPose end;
  double distance_m = 0.0;   ///< ground driven
  double goal_left_m = 0.0;  ///< straight-line distance to the goal at the end
  world::RoverPose estimate; ///< where the rover believed it ended (dead-reckoned odometry)
  int emergency_stops = 0;
  int hand_overs = 0;
  std::vector<UnsafeEvent> unsafe_events;
  std::vector<TraverseFault> faults; ///< the emulated computer's fault, when it struck
  double driving_seconds = 0.0;      ///< driving and turning at the chassis's speeds
  /// The navigation's time as mission time: 0 natively, the emulated cycles' on a platform.
  double compute_seconds = 0.0;
  double host_seconds = 0.0; ///< this machine's time for all cycles (not deterministic)
  std::vector<TraverseCycle> cycles;

  /// On success, the straight line to the goal's circle (goal_m - goal_tolerance_m) over the
  /// distance driven, as in SPL (Anderson et al. 2018); 0 otherwise.
  double path_efficiency() const;
  double mission_seconds() const { return driving_seconds + compute_seconds; }
  /// Distance between the odometry's estimate and the true end.
  double odometry_error_m() const;
};

/// Called after each cycle.
using TraverseProgress = std::function<void(const TraverseCycle&, const TraverseResult&)>;
/// Called with each cycle's left image and navigation, for pictures of what the rover saw.
using CycleView = std::function<void(int cycle, const imaging::Image<std::uint8_t>& left,
                                     const nav::NavigationResult& navigation)>;

/// The course's site: a strip goal_m + 20 m east-west by 30 m north-south, the seed, rocks and
/// slope of the settings, the clear disc around the start (the rover at the west end facing east,
/// the goal goal_m east of it).
world::TerrainSettings traverse_site(const TraverseSettings& settings);

/// Runs the loop on `terrain` (made from traverse_site(settings)): render the pair from the rover's
/// pose, navigate natively with the mission heading toward the goal, execute the drive on the true
/// ground with the inclinometer read every read_every_m, and the paper's motion scheme between
/// cycles, until the goal, a hand-over, a safety violation or max_cycles. Byte-identical for
/// identical settings. Throws std::invalid_argument for bad settings.
TraverseResult run_traverse(const world::Terrain& terrain, const TraverseSettings& settings,
                            const TraverseProgress& progress = {}, const CycleView& view = {});
/// The same on a site generated from traverse_site(settings).
TraverseResult run_traverse(const TraverseSettings& settings,
                            const TraverseProgress& progress = {});

} // namespace marsokhod::eval
