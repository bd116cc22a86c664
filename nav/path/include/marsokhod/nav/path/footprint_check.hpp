// The footprint check: the rover's whole body, driven along the commands, against the steps and
// slopes the zones found.
#pragma once

#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/work/work.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <cstddef>
#include <memory_resource>
#include <span>

namespace marsokhod::nav {

/// A step or slope point the rover's footprint covers on its way, and where.
struct FootprintConflict {
  GroundPoint hazard; ///< the point's ground position, level frame
  int command = 0;    ///< the command during which the footprint covers it
  bool turning = false;
  bool unseen = false; ///< ground the pair did not see (seen_ground.hpp), not a step or slope
};

/// How finely turns on the spot are sampled (driving straight is tested exactly: the
/// footprint translated along its own heading sweeps a rectangle).
inline constexpr double kFootprintTurnStepDeg = 2.0;

/// The step and slope pixels of `zones` whose ground points the chassis footprint covers while
/// the rover executes `commands` from the origin facing +x: on each straight leg, the rectangle
/// from half a footprint length behind its start to half a length beyond its end, a
/// footprint's width across; on each turn on the spot, the footprint at every
/// kFootprintTurnStepDeg of the turn and at its end. At most `limit` conflicts, from the
/// bottom row up (nearest first), then column order. Reports Work::footprint_scan per pixel of
/// the zone map examined and Work::footprint_test per point tested against a leg or a turn's
/// pose. Instantiated for NullMeter, CountingMeter and DynamicMeter.
template <class Meter = NullMeter>
std::pmr::vector<FootprintConflict>
footprint_conflicts(const TerrainRows& terrain, const ZoneMap& zones,
                    std::span<const DriveCommand> commands, const imaging::Chassis& chassis,
                    std::size_t limit, Meter& meter = null_meter,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// The same test for given ground points (level frame), in their order: the points the
/// footprint covers while the rover executes `commands`, at most `limit`. Reports
/// Work::footprint_scan per point given and Work::footprint_test per point tested against a
/// leg or a turn's pose.
template <class Meter = NullMeter>
std::pmr::vector<FootprintConflict>
footprint_covers(std::span<const GroundPoint> points, std::span<const DriveCommand> commands,
                 const imaging::Chassis& chassis, std::size_t limit, Meter& meter = null_meter,
                 std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
