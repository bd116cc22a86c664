// Planning, checking the drive by the footprint, and planning again around what it met.
#include "marsokhod/nav/cycle/checked_path.hpp"

#include "work/work_report.hpp"

#include "marsokhod/nav/path/footprint_check.hpp"
#include "marsokhod/nav/path/seen_ground.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace marsokhod::nav {
namespace {

// A zone byte no zone takes: ground withheld from the planner for the footprint's sake. It is
// not traversable, and it never leaves plan_cycle_path.
constexpr std::uint8_t kWithheld = 0x80;

PathPlan no_path(std::string reason, std::pmr::memory_resource* memory) {
  PathPlan plan{false, std::move(reason), {}, {}, 0.0, 0.0, std::pmr::vector<PixelPoint>(memory)};
  return plan;
}

// Withholds every traversable pixel whose ground point lies within `radius` of a conflict.
template <class Meter>
void withhold_around(const TerrainRows& terrain, std::span<const FootprintConflict> conflicts,
                     const imaging::Chassis& chassis, ZoneMap& zones, Meter& meter) {
  // Whatever its heading, the footprint covers the point only while the centre is nearer than
  // the footprint's half-diagonal.
  const double radius = imaging::footprint_reach_m(chassis);
  double x0 = std::numeric_limits<double>::infinity();
  double y0 = x0;
  double x1 = -x0;
  double y1 = -x0;
  for (const FootprintConflict& c : conflicts) {
    x0 = std::min(x0, c.hazard.x - radius);
    y0 = std::min(y0, c.hazard.y - radius);
    x1 = std::max(x1, c.hazard.x + radius);
    y1 = std::max(y1, c.hazard.y + radius);
  }
  for (int y = 0; y < terrain.height(); ++y) {
    detail::report(meter, Work::footprint_scan, static_cast<std::uint64_t>(terrain.width()));
    const TerrainRows::Row row = terrain.row(y);
    std::uint8_t* bytes = zones.zone.row(y);
    for (int x = 0; x < terrain.width(); ++x) {
      const double px = row.forward[x];
      const double py = row.left[x];
      if (bytes[x] != 0 || !(px >= x0 && px <= x1 && py >= y0 && py <= y1))
        continue;
      for (const FootprintConflict& c : conflicts) {
        detail::report(meter, Work::footprint_test, 1);
        const double dx = px - c.hazard.x;
        const double dy = py - c.hazard.y;
        if (dx * dx + dy * dy > radius * radius)
          continue;
        bytes[x] = kWithheld;
        break;
      }
    }
  }
}

// Gives the withheld pixels back their zone (they were all traversable).
template <class Meter>
void restore(ZoneMap& zones, Meter& meter) {
  for (int y = 0; y < zones.height(); ++y) {
    detail::report(meter, Work::footprint_scan, static_cast<std::uint64_t>(zones.width()));
    std::uint8_t* bytes = zones.zone.row(y);
    std::replace(bytes, bytes + zones.width(), kWithheld, std::uint8_t{0});
  }
}

std::string refusal(const FootprintConflict& first, int paths) {
  return fmt::format(
      "the rover's footprint meets {} {:.2f} m ahead, {:.2f} m {} "
      "({}), on each of the {} path{} tried",
      first.unseen ? "ground the pair did not see" : "a step or slope", first.hazard.x,
      std::abs(first.hazard.y), first.hazard.y >= 0.0 ? "left" : "right",
      first.turning ? "turning on the spot" : "driving", paths, paths == 1 ? "" : "s");
}

template <class Meter>
PathPlan checked_plan(const TerrainRows& terrain, ZoneMap& zones, const PlannerOptions& planner,
                      const DriveOptions& drive, const FootprintCheckOptions& options, Meter& meter,
                      std::pmr::memory_resource* memory) {
  // The first conflict met; once there is one, some ground is withheld until the end.
  std::optional<FootprintConflict> first;
  imaging::Chassis checked = options.chassis;
  checked.wheel_diameter_m += 2.0 * options.allowance_m;
  std::optional<SeenGround> seen;
  if (options.unseen_cell_m > 0.0)
    seen.emplace(terrain, options.unseen_cell_m, meter, memory);
  for (int attempt = 0; attempt < options.paths; ++attempt) {
    PathPlan plan = plan_path(terrain, zones, planner, meter, memory);
    if (!plan.found && !first)
      return plan;
    if (!plan.found)
      break;
    const DrivePlan commands = plan_drive(ground_path(terrain, plan.pixels, memory), drive, memory);
    std::pmr::vector<FootprintConflict> conflicts = footprint_conflicts(
        terrain, zones, commands.commands, checked, options.conflicts_per_path, meter, memory);
    if (conflicts.size() < options.conflicts_per_path && !options.remembered.empty()) {
      const std::pmr::vector<FootprintConflict> remembered =
          footprint_covers(options.remembered, commands.commands, checked,
                           options.conflicts_per_path - conflicts.size(), meter, memory);
      conflicts.insert(conflicts.end(), remembered.begin(), remembered.end());
    }
    if (seen && conflicts.size() < options.conflicts_per_path) {
      const std::pmr::vector<FootprintConflict> unseen =
          footprint_unseen(*seen, commands.commands, options.chassis,
                           options.conflicts_per_path - conflicts.size(), meter, memory);
      conflicts.insert(conflicts.end(), unseen.begin(), unseen.end());
    }
    if (conflicts.empty()) {
      if (first)
        restore(zones, meter);
      return plan;
    }
    if (!first)
      first = conflicts.front();
    withhold_around(terrain, conflicts, checked, zones, meter);
  }
  restore(zones, meter);
  return no_path(refusal(*first, options.paths), memory);
}

} // namespace

void validate(const FootprintCheckOptions& options) {
  imaging::validate(options.chassis);
  if (options.paths < 0)
    throw std::invalid_argument(
        fmt::format("footprint check: paths = {} must not be negative", options.paths));
  if (!(options.allowance_m >= 0.0) || !std::isfinite(options.allowance_m))
    throw std::invalid_argument(fmt::format(
        "footprint check: allowance_m = {} must be finite and not negative", options.allowance_m));
  if (!(options.unseen_cell_m >= 0.0) || !std::isfinite(options.unseen_cell_m))
    throw std::invalid_argument(
        fmt::format("footprint check: unseen_cell_m = {} must be finite and not negative",
                    options.unseen_cell_m));
  if (options.conflicts_per_path < 1)
    throw std::invalid_argument("footprint check: conflicts_per_path must be at least 1");
}

template <class Meter>
PathPlan plan_cycle_path(const TerrainRows& terrain, ZoneMap& zones, const PlannerOptions& planner,
                         const DriveOptions& drive, const FootprintCheckOptions& options,
                         Meter& meter, std::pmr::memory_resource* memory) {
  validate(options);
  if (terrain.known_pixels() == 0)
    return no_path("no pixel of the disparity map gives a ground point", memory);
  if (options.paths == 0)
    return plan_path(terrain, zones, planner, meter, memory);
  return checked_plan(terrain, zones, planner, drive, options, meter, memory);
}

template <class Meter>
PathPlan plan_cycle_path(const TerrainPoints& terrain, ZoneMap& zones,
                         const PlannerOptions& planner, const DriveOptions& drive,
                         const FootprintCheckOptions& options, Meter& meter,
                         std::pmr::memory_resource* memory) {
  return plan_cycle_path(ResidentTerrain(terrain), zones, planner, drive, options, meter, memory);
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template PathPlan plan_cycle_path<M>(const TerrainRows&, ZoneMap&, const PlannerOptions&,        \
                                       const DriveOptions&, const FootprintCheckOptions&, M&,      \
                                       std::pmr::memory_resource*);                                \
  template PathPlan plan_cycle_path<M>(const TerrainPoints&, ZoneMap&, const PlannerOptions&,      \
                                       const DriveOptions&, const FootprintCheckOptions&, M&,      \
                                       std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
