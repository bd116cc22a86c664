// Drive commands: the safest path's ground polyline simplified into turn-and-drive legs.

#include "marsokhod/nav/path/drive_commands.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

double degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

double range_of(const GroundPoint& p) {
  return std::hypot(p.x, p.y);
}

// The rover starts at its centre facing along level x; each leg turns towards the next
// vertex, then drives to it.
std::pmr::vector<DriveCommand> legs(std::span<const GroundPoint> polyline,
                                    std::pmr::memory_resource* memory) {
  std::pmr::vector<DriveCommand> commands(memory);
  GroundPoint at;
  double heading = 0.0;
  for (const GroundPoint& next : polyline) {
    const double dx = next.x - at.x;
    const double dy = next.y - at.y;
    const double distance = std::hypot(dx, dy);
    if (distance == 0.0)
      continue;
    const double bearing = std::atan2(dy, dx);
    commands.push_back(
        {degrees(std::remainder(bearing - heading, 2.0 * std::numbers::pi)), distance});
    at = next;
    heading = bearing;
  }
  return commands;
}

} // namespace

void validate(const DriveOptions& options) {
  if (!std::isfinite(options.tolerance_m) || options.tolerance_m <= 0.0)
    throw std::invalid_argument(fmt::format(
        "drive option tolerance_m = {}: must be finite and positive", options.tolerance_m));
}

DrivePlan plan_drive(std::span<const GroundPoint> ground_path, const DriveOptions& options,
                     std::pmr::memory_resource* memory) {
  validate(options);
  if (ground_path.empty())
    throw std::invalid_argument("plan_drive: the path has no point");
  DrivePlan plan{std::pmr::vector<GroundPoint>(ground_path.begin(), ground_path.end(), memory),
                 std::pmr::vector<GroundPoint>(memory),
                 0.0,
                 std::pmr::vector<double>(memory),
                 0.0,
                 std::pmr::vector<DriveCommand>(memory)};
  for (const std::size_t index : simplify_polyline(ground_path, options.tolerance_m, memory))
    plan.polyline.push_back(ground_path[index]);
  plan.start_m = range_of(plan.polyline.front());
  plan.target_m = range_of(plan.polyline.back());
  for (std::size_t i = 1; i + 1 < plan.polyline.size(); ++i)
    plan.fracture_m.push_back(range_of(plan.polyline[i]));
  plan.commands = legs(plan.polyline, memory);
  return plan;
}

std::pmr::vector<GroundPoint> ground_path(const TerrainRows& terrain,
                                          std::span<const PixelPoint> path,
                                          std::pmr::memory_resource* memory) {
  std::pmr::vector<GroundPoint> ground(memory);
  ground.reserve(path.size());
  for (const PixelPoint& pixel : path) {
    if (!terrain.contains(pixel.x, pixel.y))
      throw std::invalid_argument(fmt::format(
          "plan_drive: path pixel ({}, {}) has no known ground point", pixel.x, pixel.y));
    const TerrainRows::Row row = terrain.row(pixel.y);
    if (!row.known(pixel.x))
      throw std::invalid_argument(fmt::format(
          "plan_drive: path pixel ({}, {}) has no known ground point", pixel.x, pixel.y));
    ground.push_back({row.forward[pixel.x], row.left[pixel.x]});
  }
  return ground;
}

std::pmr::vector<GroundPoint> ground_path(const TerrainPoints& terrain,
                                          std::span<const PixelPoint> path,
                                          std::pmr::memory_resource* memory) {
  return ground_path(ResidentTerrain(terrain), path, memory);
}

DrivePlan plan_drive(const TerrainPoints& terrain, std::span<const PixelPoint> path,
                     const DriveOptions& options, std::pmr::memory_resource* memory) {
  return plan_drive(ground_path(terrain, path, memory), options, memory);
}

} // namespace marsokhod::nav
