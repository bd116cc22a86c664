// Testing the step and slope points of the zones against the footprint swept by the commands.
#include "marsokhod/nav/path/footprint_check.hpp"

#include "work/work_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace marsokhod::nav {
namespace {

// One command as the rover executes it: a turn on the spot at `pivot` from `heading_before` by
// `turn_rad`, then a straight drive of `distance_m` along the new heading.
struct Leg {
  GroundPoint pivot;
  double heading_before = 0.0;
  double turn_rad = 0.0;
  double distance_m = 0.0;
  double cos_h = 1.0;
  double sin_h = 0.0;
};

std::pmr::vector<Leg> legs_of(std::span<const DriveCommand> commands,
                              std::pmr::memory_resource* memory) {
  std::pmr::vector<Leg> legs(memory);
  legs.reserve(commands.size());
  GroundPoint at;
  double heading = 0.0;
  for (const DriveCommand& command : commands) {
    Leg leg{at, heading, command.turn_deg * std::numbers::pi / 180.0, command.distance_m, 1.0, 0.0};
    heading += leg.turn_rad;
    leg.cos_h = std::cos(heading);
    leg.sin_h = std::sin(heading);
    at = GroundPoint{at.x + command.distance_m * leg.cos_h, at.y + command.distance_m * leg.sin_h};
    legs.push_back(leg);
  }
  return legs;
}

struct Box {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// Every point the footprint can reach on the way lies in this box.
Box reach_box(std::span<const Leg> legs, double reach) {
  Box box{-reach, -reach, reach, reach};
  for (const Leg& leg : legs) {
    const double ex = leg.pivot.x + leg.distance_m * leg.cos_h;
    const double ey = leg.pivot.y + leg.distance_m * leg.sin_h;
    box.x0 = std::min({box.x0, leg.pivot.x - reach, ex - reach});
    box.y0 = std::min({box.y0, leg.pivot.y - reach, ey - reach});
    box.x1 = std::max({box.x1, leg.pivot.x + reach, ex + reach});
    box.y1 = std::max({box.y1, leg.pivot.y + reach, ey + reach});
  }
  return box;
}

// The rectangle the footprint sweeps driving straight: in the leg's frame, from half a length
// behind the pivot to half a length beyond the end, half a width to either side.
bool under_drive(const Leg& leg, const imaging::Chassis& chassis, double x, double y) {
  const double dx = x - leg.pivot.x;
  const double dy = y - leg.pivot.y;
  const double along = dx * leg.cos_h + dy * leg.sin_h;
  const double across = -dx * leg.sin_h + dy * leg.cos_h;
  const double half_length = 0.5 * chassis.length_m();
  return std::abs(across) <= 0.5 * chassis.width_m() &&
         along >= std::min(0.0, leg.distance_m) - half_length &&
         along <= std::max(0.0, leg.distance_m) + half_length;
}

// The turn's poses, its first included (the first command's pose is where the rover stands).
template <class Meter>
bool under_turn(const Leg& leg, const imaging::Chassis& chassis, double reach, double x, double y,
                Meter& meter) {
  if (leg.turn_rad == 0.0 || std::hypot(x - leg.pivot.x, y - leg.pivot.y) > reach)
    return false;
  const double step = kFootprintTurnStepDeg * std::numbers::pi / 180.0;
  const int samples = std::max(1, static_cast<int>(std::ceil(std::abs(leg.turn_rad) / step)));
  detail::report(meter, Work::footprint_test, static_cast<std::uint64_t>(samples + 1));
  for (int i = 0; i <= samples; ++i) {
    const imaging::PlanarPose pose{leg.pivot.x, leg.pivot.y,
                                   leg.heading_before + leg.turn_rad * i / samples};
    if (imaging::under_footprint(chassis, pose, x, y))
      return true;
  }
  return false;
}

// The first leg whose footprint covers (px, py), and whether it covers it turning.
template <class Meter>
std::optional<FootprintConflict> conflict_at(std::span<const Leg> legs,
                                             const imaging::Chassis& chassis, double reach,
                                             double px, double py, Meter& meter) {
  for (std::size_t c = 0; c < legs.size(); ++c) {
    const bool turning = under_turn(legs[c], chassis, reach, px, py, meter);
    detail::report(meter, Work::footprint_test, 1);
    if (turning || under_drive(legs[c], chassis, px, py))
      return FootprintConflict{GroundPoint{px, py}, static_cast<int>(c), turning};
  }
  return std::nullopt;
}

} // namespace

template <class Meter>
std::pmr::vector<FootprintConflict>
footprint_covers(std::span<const GroundPoint> points, std::span<const DriveCommand> commands,
                 const imaging::Chassis& chassis, std::size_t limit, Meter& meter,
                 std::pmr::memory_resource* memory) {
  std::pmr::vector<FootprintConflict> conflicts(memory);
  const std::pmr::vector<Leg> legs = legs_of(commands, memory);
  const double reach = imaging::footprint_reach_m(chassis);
  const Box box = reach_box(legs, reach);
  detail::report(meter, Work::footprint_scan, static_cast<std::uint64_t>(points.size()));
  for (const GroundPoint& p : points) {
    if (conflicts.size() >= limit)
      break;
    if (!box.contains(p.x, p.y))
      continue;
    if (const auto conflict =
            conflict_at(std::span<const Leg>(legs), chassis, reach, p.x, p.y, meter))
      conflicts.push_back(*conflict);
  }
  return conflicts;
}

template <class Meter>
std::pmr::vector<FootprintConflict>
footprint_conflicts(const TerrainRows& terrain, const ZoneMap& zones,
                    std::span<const DriveCommand> commands, const imaging::Chassis& chassis,
                    std::size_t limit, Meter& meter, std::pmr::memory_resource* memory) {
  std::pmr::vector<FootprintConflict> conflicts(memory);
  const std::pmr::vector<Leg> legs = legs_of(commands, memory);
  const double reach = imaging::footprint_reach_m(chassis);
  const Box box = reach_box(legs, reach);
  for (int y = terrain.height() - 1; y >= 0 && conflicts.size() < limit; --y) {
    detail::report(meter, Work::footprint_scan, static_cast<std::uint64_t>(terrain.width()));
    const TerrainRows::Row row = terrain.row(y);
    for (int x = 0; x < terrain.width() && conflicts.size() < limit; ++x) {
      const Zone zone = zones.at(x, y);
      if (zone != Zone::step && zone != Zone::slope)
        continue;
      const double px = row.forward[x];
      const double py = row.left[x];
      if (!box.contains(px, py))
        continue;
      if (const auto conflict =
              conflict_at(std::span<const Leg>(legs), chassis, reach, px, py, meter))
        conflicts.push_back(*conflict);
    }
  }
  return conflicts;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template std::pmr::vector<FootprintConflict> footprint_conflicts<M>(                             \
      const TerrainRows&, const ZoneMap&, std::span<const DriveCommand>, const imaging::Chassis&,  \
      std::size_t, M&, std::pmr::memory_resource*);                                                \
  template std::pmr::vector<FootprintConflict> footprint_covers<M>(                                \
      std::span<const GroundPoint>, std::span<const DriveCommand>, const imaging::Chassis&,        \
      std::size_t, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
