// The ground a stereo pair saw, and the footprint's sweep over ground it did not see.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/path/footprint_check.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <memory_resource>
#include <span>
#include <vector>

namespace marsokhod::nav {

/// Cells of a level grid (frame of the terrain's points, within 30 m) that hold at least one known
/// ground point. Ground in no such cell was hidden from the pair (behind a rock, outside the view)
/// or gave no disparity: what lies there is not known, and a safe drive does not cross it.
class SeenGround {
public:
  /// Builds the grid from every known point of `terrain`, `cell_m` a side (> 0). Reports
  /// Work::footprint_scan per pixel read.
  template <class Meter = NullMeter>
  SeenGround(const TerrainRows& terrain, double cell_m, Meter& meter = null_meter,
             std::pmr::memory_resource* memory = std::pmr::get_default_resource());

  /// Whether the cell of (x, y) or one of its eight neighbours holds a point: the points of a
  /// row of pixels lie further apart with range than one cell.
  bool seen(double x, double y) const;
  /// Distance from the rover of the nearest known point, m (infinity without one): ground
  /// nearer lies below the cameras' view, known from the rover's earlier cycles.
  double nearest_m() const { return nearest_m_; }
  double cell_m() const { return cell_m_; }

private:
  bool cell(long column, long row) const;

  double cell_m_;
  double x0_ = 0.0;
  double y0_ = 0.0;
  long columns_ = 0;
  long rows_ = 0;
  double nearest_m_;
  std::pmr::vector<std::uint8_t> cells_;
};

/// Points of the ground the footprint covers while the rover executes `commands` (driving and
/// turning on the spot, the first leg included) that `seen` did not see, sampled every half
/// cell, at least one cell beyond seen.nearest_m() from the rover; at most `limit`, the
/// earliest on the way first. Reports Work::footprint_test per sample.
template <class Meter = NullMeter>
std::pmr::vector<FootprintConflict>
footprint_unseen(const SeenGround& seen, std::span<const DriveCommand> commands,
                 const imaging::Chassis& chassis, std::size_t limit, Meter& meter = null_meter,
                 std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
