// The honest judge of a path: the rover's whole footprint, driven along its commands on the
// true ground, must miss every true obstacle.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/path/drive_poses.hpp"
#include "marsokhod/world/scene/rover_placement.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <span>
#include <string>

namespace marsokhod::eval {

/// The first obstacle node the footprint covers, and where the rover was then.
struct FootprintHit {
  double x_m = 0.0;     ///< the obstacle node, level frame of the cycle's start (ahead)
  double y_m = 0.0;     ///< (left)
  double z_m = 0.0;     ///< its height, level frame
  double range_m = 0.0; ///< its ground distance from the rover's starting centre
  nav::DrivePose pose;  ///< the rover's pose when its footprint first covered an obstacle
  /// The footprint's corners then, on the true ground, level frame (for pictures).
  std::array<Eigen::Vector3d, 4> corners{};
  /// What the navigation made of the node, when known ("margin", "unknown", "hidden from the
  /// left camera", ...); empty until the caller says.
  std::string seen_as;
};

/// What the footprint judge found; no hit means the drive is safe.
struct FootprintVerdict {
  std::optional<FootprintHit> hit;
  bool unsafe() const { return hit.has_value(); }
};

/// The first obstacle node the footprint covers at one pose of the drive (nav::drive_poses, in
/// the level frame of the placement), and where; none when it covers none. Nodes outside the
/// terrain count as obstacles.
std::optional<FootprintHit> footprint_hit_at(const world::Terrain& terrain,
                                             const world::RoverPlacement& placement,
                                             const nav::DrivePose& pose,
                                             const imaging::Chassis& chassis = {});

/// Executes `commands` from the rover's placement on the true terrain (the level frame of the
/// placement, its heading) and sweeps the chassis footprint (imaging::Chassis) over the
/// terrain's obstacle map at every pose (nav::drive_poses: every 5 cm driving, every 2 degrees
/// turning, the turns on the spot included). Nodes outside the terrain count as obstacles: the
/// site ends there.
FootprintVerdict judge_footprint(const world::Terrain& terrain,
                                 const world::RoverPlacement& placement,
                                 std::span<const nav::DriveCommand> commands,
                                 const imaging::Chassis& chassis = {});

/// "obstacle 4.26 m away (4.21 ahead, 0.62 left), 3.90 m into the drive, leg 2 driving".
std::string describe(const FootprintHit& hit);

} // namespace marsokhod::eval
