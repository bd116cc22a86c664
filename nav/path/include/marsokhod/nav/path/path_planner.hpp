// The safest path: planner options, the row sweep over the pixel graph and plan_path.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/work/work.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <cstdint>
#include <limits>
#include <memory_resource>
#include <string>

namespace marsokhod::nav {

/// How the safest path is chosen (docs/navigation.md, "Safest path").
struct PlannerOptions {
  /// Mission heading relative to the rover's heading, degrees, counter-clockwise (left)
  /// positive; the virtual destination keeps the rover on it.
  double heading_deg = 0.0;
  /// Ground distances from the rover centre between which the destination is chosen (the
  /// paper's normal path range is 10-12 m; 3-4 m after an emergency stop).
  double target_min_m = 10.0;
  double target_max_m = 12.0;
  /// The start is the nearest traversable pixel in front of the rover (|level y| at most
  /// start_lateral_m) no farther than start_max_m; farther means the way out is blocked. The
  /// rover drives straight to it, so there is none behind a step or slope in front.
  double start_lateral_m = 0.25;
  double start_max_m = 3.5;
  /// Starts tried in all. The nearest start may lie in a pocket that a prohibited zone
  /// closes; then the nearest traversable point in front above the rows the sweep reached
  /// there is tried next, so that a dead end right in front does not hide the way beyond it.
  int start_attempts = 4;
  /// Tie-break added to every edge: this much cost per metre of ground between its two ends,
  /// so that on flat ground the shortest, straightest path wins.
  double length_weight = 0.02;
  /// Elevation differences up to this much count as level: below it they are the stereo's
  /// noise (a fraction of a pixel of disparity), not relief, and summed over a hundred rows
  /// they would outweigh the length tie-break and make the path wander on flat ground.
  double flat_tolerance_m = 0.02;
  /// Cost per radian between the destination's bearing and the mission heading.
  double heading_weight = 0.5;
  /// Longest ground step between the points of two consecutive rows the path may take: a
  /// longer one crosses ground the mast cannot see (behind a crater rim, in a pit), which may
  /// hide a step. Level ground seen by the 256-pixel rig is some 0.35 m a row at 12 m.
  double max_edge_m = 0.6;
};

/// The weight of one edge of the graph: max(0, |H_i - H_j| - flat_tolerance_m) plus
/// length_weight times the ground distance between the two points; no edge where that
/// distance exceeds max_edge_m.
struct EdgeWeights {
  double length_weight = 0.02;
  double flat_tolerance_m = 0.02;
  double max_edge_m = std::numeric_limits<double>::infinity();
};

/// The edge weights a plan with these options uses.
inline EdgeWeights edge_weights(const PlannerOptions& options) {
  return EdgeWeights{options.length_weight, options.flat_tolerance_m, options.max_edge_m};
}

/// Throws std::invalid_argument naming the first option out of range.
void validate(const PlannerOptions& options);

/// A pixel of the left image: column x, row y.
struct PixelPoint {
  int x = 0;
  int y = 0;
  friend bool operator==(const PixelPoint&, const PixelPoint&) = default;
};

/// Column step from a pixel to its predecessor in the row below, or none.
inline constexpr std::int8_t kNoPredecessor = 2;

/// Costs of the row sweep: the cheapest way from the start to every pixel of the rows
/// first_row..start.y over the graph of fig. 1 (each traversable pixel of row y reached from
/// the three pixels x-1, x, x+1 of row y+1, edges weighted as EdgeWeights says).
struct RowSweep {
  imaging::Image<float> cost;       ///< +inf where unreachable or outside the swept rows
  imaging::Image<std::int8_t> from; ///< -1, 0, +1 or kNoPredecessor
  PixelPoint start;
  int first_row = 0;
};

/// One sweep over the rows from start.y up to first_row: O(pixels). The start must be a
/// traversable pixel (std::invalid_argument otherwise). Reports Work::path_relaxation per
/// edge examined. Instantiated for NullMeter, CountingMeter and DynamicMeter.
template <class Meter = NullMeter>
RowSweep sweep_rows(const TerrainPoints& terrain, const ZoneMap& zones, PixelPoint start,
                    int first_row, const EdgeWeights& weights, Meter& meter = null_meter,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource());
template <class Meter = NullMeter>
RowSweep sweep_rows(const TerrainRows& terrain, const ZoneMap& zones, PixelPoint start,
                    int first_row, const EdgeWeights& weights, Meter& meter = null_meter,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// The safest path over the traversable pixels, start first.
struct PathPlan {
  bool found = false;
  std::string reason; ///< why no path, when found is false
  PixelPoint start;
  PixelPoint target;
  double cost = 0.0;  ///< sum of the path's edge weights
  double score = 0.0; ///< cost plus the heading penalty of the target
  std::pmr::vector<PixelPoint> pixels;
};

/// Finds the start (trying up to start_attempts starts, nearest first), sweeps the rows, picks the
/// virtual destination with the lowest cost plus heading penalty among the reachable pixels
/// target_min_m..target_max_m away, and rebuilds the path from it back to the start
/// (Work::path_backtrack per step). A plan that cannot be made is found = false with a reason.
/// Throws std::invalid_argument for bad options or zones of another size than the terrain.
template <class Meter = NullMeter>
PathPlan plan_path(const TerrainPoints& terrain, const ZoneMap& zones,
                   const PlannerOptions& options, Meter& meter = null_meter,
                   std::pmr::memory_resource* memory = std::pmr::get_default_resource());
/// plan_path on terrain read row by row.
template <class Meter = NullMeter>
PathPlan plan_path(const TerrainRows& terrain, const ZoneMap& zones, const PlannerOptions& options,
                   Meter& meter = null_meter,
                   std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
