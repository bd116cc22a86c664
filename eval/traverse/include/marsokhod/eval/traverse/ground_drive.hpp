// Executing drive commands on the true ground: the inclinometer read as the rover goes, the
// footprint judged against the true obstacles.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/cycle/motion_scheme.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <Eigen/Core>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// What the chassis watches while it drives.
struct GroundDriveLimits {
  double emergency_tilt_deg = 20.0; ///< the inclinometer stops the rover over this
  double tilt_limit_deg = 25.0;     ///< over this the rover is unsafe
  double read_every_m = 0.25;       ///< the inclinometer's reading interval along the way
  /// Where the drive ends early: the goal reached (no goal: never).
  std::optional<Eigen::Vector2d> goal;
  double goal_tolerance_m = 1.5;
};

/// How a drive on the true ground went.
struct GroundDrive {
  world::RoverPose end;
  double driven_m = 0.0;
  double turned_deg = 0.0;            ///< absolute turning done
  std::vector<Eigen::Vector2d> track; ///< the centre, world frame, at every reading
  bool emergency_stop = false;
  nav::Side risen_side = nav::Side::left; ///< the side that rose, on an emergency stop
  double tilt_deg = 0.0;                  ///< the reading that stopped the rover
  bool at_goal = false;
  /// A safety violation: the footprint on a true obstacle, or a tilt over the limit.
  std::optional<std::string> unsafe;
  Eigen::Vector2d unsafe_at = Eigen::Vector2d::Zero();
};

/// The rover's tilt from the vertical, degrees, for an attitude.
double tilt_deg(double pitch_deg, double roll_deg);

/// Executes `commands` (nav's convention: from the rover's pose, turn then drive) from `start`
/// on the true terrain, at nav::drive_poses' sampling. The inclinometer (pitch and roll of the
/// chassis settled on the six wheel contacts) is read at the start, every read_every_m and at
/// every pose of a turn; a reading over emergency_tilt_deg, and more than 0.5 deg over the
/// drive's first reading (a rover already standing over the threshold after an emergency stop
/// turns and drives away without stopping again), stops the rover there. The drive is
/// unsafe when the footprint covers a true obstacle node (eval::footprint_hit_at) before the
/// rover stops, or a reading is over tilt_limit_deg; the rover stops there too.
GroundDrive drive_on_ground(const world::Terrain& terrain, const world::RoverPose& start,
                            std::span<const nav::DriveCommand> commands,
                            const imaging::Chassis& chassis, const GroundDriveLimits& limits);

} // namespace marsokhod::eval
