// The hazard memory: the steps and slopes of the last cycles, kept where the odometry put them.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <cstdint>
#include <deque>
#include <set>
#include <utility>
#include <vector>

namespace marsokhod::nav {

/// The step and slope points of the last few cycles, kept in the odometry's frame on a grid, so
/// that a cycle can check the ground its drive begins on: the strip just below its cameras'
/// view, which an earlier cycle saw from farther back (FootprintCheckOptions::remembered). The
/// paper's cycle keeps nothing between cycles; this is what the footprint check adds to it.
class HazardMemory {
public:
  /// Keeps the points of the last `cycles` cycles (at least 1), one per cell of `cell_m`.
  /// Throws std::invalid_argument for other values.
  explicit HazardMemory(int cycles = 2, double cell_m = 0.05);

  /// This cycle's step and slope points, seen by the rover standing at `pose` (odometry frame:
  /// x, y in metres, heading counter-clockwise from x). Forgets the oldest cycle beyond the
  /// kept number.
  void remember(const TerrainPoints& terrain, const ZoneMap& zones,
                const imaging::PlanarPose& pose);

  /// The kept points within `radius_m` of `pose`, in its level frame (x ahead, y left), each
  /// cell once, in the cells' order (deterministic).
  std::vector<GroundPoint> recall(const imaging::PlanarPose& pose, double radius_m) const;

  void clear() { cycles_.clear(); }

private:
  using Cell = std::pair<std::int64_t, std::int64_t>;
  int kept_;
  double cell_m_;
  std::deque<std::set<Cell>> cycles_;
};

} // namespace marsokhod::nav
