#pragma once

// The stages of find_zones (zones.hpp), each returning the comparisons it made so that the
// caller can report them to its meter. They work on the visible points binned into a ground
// grid (ground_grid.hpp) and write their verdicts into the pixels' zones.

#include "ground_grid.hpp"

#include "marsokhod/nav/elevation.hpp"
#include "marsokhod/nav/zones.hpp"

#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// Absolute slack of the ordering test, metres, on top of ZoneOptions::order_tolerance.
inline constexpr double kOrderSlack_m = 0.05;

/// Marks Zone::unknown on pixels whose ground distance contradicts their column. Seen from
/// above, ground farther up the image is never nearer, so a column's distances, read from the
/// bottom row up, never decrease. The longest non-decreasing sequence of the column's judged pixels
/// (not necessarily contiguous) is taken as what was seen; a pixel off it that lies farther than
/// the next pixel of the run above it, or nearer than the last one below it, by more than
/// order_tolerance (relative) plus kOrderSlack_m, is a mismatch. A whole cluster of mismatches (a
/// rock whose disparity lay outside the search, matched to the wrong place) is outvoted by the rest
/// of its column, which a comparison with the next few rows alone would not see. Returns the
/// comparisons made.
std::uint64_t mark_out_of_order(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone, std::pmr::memory_resource* memory);

/// Turns back to Zone::traversable the runs of unknown pixels along a row that have a
/// (filled-in) ground point and whose two traversable ends are less than bridged_gap_m apart
/// on the ground and within max_step_m of each other in height. Returns the tests made.
std::uint64_t bridge_small_gaps(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone);

/// Cells of the grid within `distance_m` along each axis: at least one.
int cells_within(const GroundGrid& grid, double distance_m);

/// Cells r apart along an axis such that any two points of cells at most r apart lie within
/// `distance_m` of each other along it: the largest r with (r + 1) cells <= distance_m, at least
/// one.
int cells_apart_within(const GroundGrid& grid, double distance_m);

/// Marks Zone::step on traversable pixels: some binned point in the cells
/// cells_apart_within(step_baseline_m) around the pixel's own cell, along both ground axes, is
/// higher or lower than the pixel's own point by more than max_step_m. Every pair compared lies
/// within the baseline: a window of whole cells reaching a cell further would also compare points
/// up to a cell beyond it, and read the foot of every rock as a step a baseline away.
std::uint64_t mark_steps(const GroundGrid& grid, const TerrainPoints& terrain,
                         const ZoneOptions& options, Image<std::uint8_t>& zone,
                         std::pmr::memory_resource* memory);

/// Marks Zone::slope on traversable pixels whose cell's fitted plane is too steep.
std::uint64_t mark_slopes(const GroundGrid& grid, const ZoneOptions& options,
                          Image<std::uint8_t>& zone, std::pmr::memory_resource* memory);

/// Sets `verdict` on the traversable pixels whose cell is flagged (non-zero) in `flagged`.
void mark_flagged_cells(const GroundGrid& grid, const std::pmr::vector<std::uint8_t>& flagged,
                        Zone verdict, Image<std::uint8_t>& zone);

/// Marks Zone::margin on traversable pixels whose cell lies within the rover's half-width of a
/// cell holding a step or slope pixel.
std::uint64_t grow_margin(const GroundGrid& grid, const ZoneOptions& options,
                          Image<std::uint8_t>& zone, std::pmr::memory_resource* memory);

} // namespace marsokhod::nav::detail
