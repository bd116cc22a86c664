// The rover's poses while it executes drive commands, for sweeping its footprint.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"

#include <memory_resource>
#include <span>
#include <vector>

namespace marsokhod::nav {

/// One pose of the rover on its way, in the level frame of the cycle's start (the rover's
/// centre at the origin facing +x).
struct DrivePose {
  imaging::PlanarPose pose;
  double along_m = 0.0; ///< ground driven before this pose
  int command = 0;      ///< index of the command being executed
  bool turning = false; ///< true while turning on the spot
};

/// How finely the poses sample the commands.
struct DriveSweepOptions {
  double step_m = 0.05;       ///< at most this far between poses while driving
  double turn_step_deg = 2.0; ///< at most this much turn between poses while turning
};

/// Every pose from the start (the origin, heading 0) through each command: a turn on the spot
/// sampled every turn_step_deg, then the straight drive every step_m, each command's last pose
/// exact; its memory from `memory`. Throws std::invalid_argument for non-positive steps or
/// non-finite commands.
std::pmr::vector<DrivePose>
drive_poses(std::span<const DriveCommand> commands, const DriveSweepOptions& options = {},
            std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
