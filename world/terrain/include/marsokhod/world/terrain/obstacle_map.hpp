// The ground truth's obstacle map: the terrain judged against the rover's locomotion limits.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/world/terrain/height_field.hpp"

#include <cstdint>

namespace marsokhod::world {

/// The rover's locomotion limits, which decide what the ground truth calls an obstacle.
struct LocomotionLimits {
  double max_step_m = 0.30;       ///< the paper: obstacles whose vertical size exceeds 30 cm
  double max_slope_deg = 25.0;    ///< steepest slope the six-wheel chassis climbs
  double step_baseline_m = 0.30;  ///< horizontal span over which a step is measured
  double slope_baseline_m = 0.60; ///< horizontal span over which a slope is measured
};

/// Throws std::invalid_argument naming the first non-positive or non-finite limit
/// (max_slope_deg must be below 90).
void validate(const LocomotionLimits& limits);

/// Value of an obstacle node in obstacle maps; free nodes are 0.
inline constexpr std::uint8_t kObstacle = 255;

/// Recomputes an obstacle map for a height field (used by Terrain::generate() and by hand-made
/// scenes). A node is an obstacle (255) when
///  - step: some node within s = max(1, round(step_baseline_m / cell)) nodes along both x and y
///    (a square window) is higher or lower than it by more than max_step_m, or
///  - slope: the plane fitted to the 3 x 3 samples at offsets {-d, 0, d} nodes, with
///    d = max(1, round(slope_baseline_m / (2 cell))), is steeper than max_slope_deg; the
///    gradient along x is (mean of column +d - mean of column -d) / (2 d cell), likewise along y
///    (samples clamp to the grid, and the distance between the clamped columns is used).
/// Throws std::invalid_argument for non-positive or non-finite limits.
imaging::Image<std::uint8_t> obstacle_map(const HeightField& height,
                                          const LocomotionLimits& limits);

} // namespace marsokhod::world
