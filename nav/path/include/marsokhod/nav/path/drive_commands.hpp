// Drive commands: turn-then-drive legs from a path, and the polyline simplification.
#pragma once

#include "marsokhod/nav/path/path_planner.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include <memory_resource>
#include <span>

namespace marsokhod::nav {

/// A point on the ground in the level frame: x ahead of the rover centre, y to its left, m.
struct GroundPoint {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const GroundPoint&, const GroundPoint&) = default;
};

/// Turn on the spot (degrees, counter-clockwise positive), then drive straight (metres).
struct DriveCommand {
  double turn_deg = 0.0;
  double distance_m = 0.0;
};

/// How a pixel path becomes drive commands (docs/navigation.md, "Drive commands").
struct DriveOptions {
  /// Douglas-Peucker tolerance: no point of the path lies farther than this from the
  /// simplified polyline, metres.
  double tolerance_m = 0.15;
};

/// Throws std::invalid_argument unless the tolerance is finite and positive.
void validate(const DriveOptions& options);

/// The path as the rover executes it.
struct DrivePlan {
  std::pmr::vector<GroundPoint> ground_path; ///< every path pixel's ground point
  /// The simplified path: start, the fracture points (the paper's turns), target.
  std::pmr::vector<GroundPoint> polyline;
  double start_m = 0.0; ///< ground distance of the start from the rover centre
  std::pmr::vector<double> fracture_m;
  double target_m = 0.0;
  /// From the rover centre facing its heading: first to the start, then along the polyline.
  std::pmr::vector<DriveCommand> commands;
};

/// Indices of the points Douglas-Peucker keeps (always the first and the last), in order.
std::pmr::vector<std::size_t>
simplify_polyline(std::span<const GroundPoint> points, double tolerance_m,
                  std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Simplifies a ground path (at least one point) and derives distances and commands. Throws
/// std::invalid_argument for an empty path or bad options.
DrivePlan plan_drive(std::span<const GroundPoint> ground_path, const DriveOptions& options,
                     std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// The ground points of a pixel path over the terrain; std::invalid_argument for a pixel with
/// no known point.
std::pmr::vector<GroundPoint>
ground_path(const TerrainPoints& terrain, std::span<const PixelPoint> path,
            std::pmr::memory_resource* memory = std::pmr::get_default_resource());
std::pmr::vector<GroundPoint>
ground_path(const TerrainRows& terrain, std::span<const PixelPoint> path,
            std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// The same for a pixel path over the terrain (each pixel must be known).
DrivePlan plan_drive(const TerrainPoints& terrain, std::span<const PixelPoint> path,
                     const DriveOptions& options,
                     std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
