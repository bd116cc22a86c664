// The cycle's path: the planner's safest path, checked by the rover's footprint before it is sent.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/path/path_planner.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/work/work.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <cstddef>
#include <memory_resource>
#include <span>

namespace marsokhod::nav {

/// How the chosen path is checked by the rover's footprint (docs/navigation.md, "Footprint
/// check"). The zones' margin keeps the centre line half a width from every step and slope;
/// the footprint also reaches half its length ahead and behind, and sweeps a disc turning on
/// the spot at each fracture point.
struct FootprintCheckOptions {
  imaging::Chassis chassis;
  /// Paths tried in all; each refusal prohibits, for the next plan, the ground within the
  /// footprint's reach of the steps and slopes it met. 0 sends the first path unchecked.
  int paths = 6;
  /// Steps and slopes kept per refusal (the nearest first).
  std::size_t conflicts_per_path = 32;
  /// The footprint is checked this much longer ahead and behind than the chassis: the world
  /// judges a step over 0.30 m (LocomotionLimits::step_baseline_m), the zones over 0.20 m
  /// (ZoneOptions::step_baseline_m), so a step point the zones place lies up to 0.10 m inside
  /// the ground the truth forbids. Across, the zones' margin already keeps the centre line
  /// half a width away, and a wider check would refuse every path along a margin's edge.
  double allowance_m = 0.10;
  /// Steps and slopes earlier cycles saw, in this cycle's level frame (nav::HazardMemory):
  /// the drive begins on ground just below the cameras' view, which this cycle cannot see.
  /// Checked like the zones' own, after them; the points must outlive the cycle.
  std::span<const GroundPoint> remembered;
  /// Cell of the grid of seen ground (nav::SeenGround), m; the footprint must then stay on
  /// ground the pair saw, beyond the nearest ground it shows. 0 lets it cross unseen ground.
  double unseen_cell_m = 0.0;
};

/// Throws std::invalid_argument naming the first option out of range.
void validate(const FootprintCheckOptions& options);

/// The cycle's safest path: plan_path; then (options.paths > 0) the drive commands of the path
/// (plan_drive with `drive`) are checked by footprint_conflicts, and on a conflict the ground
/// within the footprint's reach of the conflicting points is withheld from the planner and the
/// path planned again, up to options.paths paths; when every one meets a step or slope, no
/// path, saying where. No path either when no pixel of the terrain is known. `zones` is
/// marked while planning and restored before returning. Instantiated for NullMeter,
/// CountingMeter and DynamicMeter.
template <class Meter = NullMeter>
PathPlan plan_cycle_path(const TerrainRows& terrain, ZoneMap& zones, const PlannerOptions& planner,
                         const DriveOptions& drive, const FootprintCheckOptions& options,
                         Meter& meter = null_meter,
                         std::pmr::memory_resource* memory = std::pmr::get_default_resource());
template <class Meter = NullMeter>
PathPlan plan_cycle_path(const TerrainPoints& terrain, ZoneMap& zones,
                         const PlannerOptions& planner, const DriveOptions& drive,
                         const FootprintCheckOptions& options, Meter& meter = null_meter,
                         std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
