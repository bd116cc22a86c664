// The stages of the prohibited-zone search (private to the zones room).
#pragma once

// The stages of find_zones (zones.hpp), each returning the comparisons it made so that the
// caller can report them to its meter. They work on the visible points binned into a ground
// grid (ground_grid.hpp): the step, slope and margin rules decide per cell what they can, and
// judge_pixels() then writes every pixel's verdict in one pass.

#include "zones/ground_grid.hpp"

#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// Absolute slack of the ordering test, metres, on top of ZoneOptions::order_tolerance.
inline constexpr double kOrderSlack_m = 0.05;

/// A pixel find_zones holds back between mark_unknown and bridge_small_gaps: seen and in range,
/// but not reliable, so a bridged gap may still turn it traversable. Never left in a zone map.
inline constexpr std::uint8_t kUnreliable = 5;

/// Writes Zone::unknown where nothing was seen or the point lies beyond max_range_m,
/// kUnreliable where (with unreliable_is_unknown) only `reliable` (0) rejects the point, and
/// Zone::traversable elsewhere, into the single-channel `zone`. Returns whether any pixel is
/// kUnreliable.
bool mark_unknown(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> reliable,
                  const ZoneOptions& options, imaging::Image<std::uint8_t>& zone);

/// Marks Zone::unknown on pixels whose ground distance contradicts their column. Seen from
/// above, ground farther up the image is never nearer, so a column's distances, read from the
/// bottom row up, never decrease. The longest non-decreasing sequence of the column's judged pixels
/// (not necessarily contiguous) is taken as what was seen; a pixel off it that lies farther than
/// the next pixel of the run above it, or nearer than the last one below it, by more than
/// order_tolerance (relative) plus kOrderSlack_m, is a mismatch. A whole cluster of mismatches (a
/// rock whose disparity lay outside the search, matched to the wrong place) is outvoted by the rest
/// of its column, which a comparison with the next few rows alone would not see. Returns the
/// comparisons made.
/// The columns are gathered `band_columns` at a time (0: all at once), each band in one pass
/// over the rows; the result is the same.
std::uint64_t mark_out_of_order(const TerrainRows& terrain, const ZoneOptions& options,
                                imaging::Image<std::uint8_t>& zone,
                                std::pmr::memory_resource* memory, int band_columns = 0);

/// Turns back to Zone::traversable the runs of kUnreliable pixels along a row of the
/// single-channel `zone` whose two traversable ends are less than bridged_gap_m apart on the
/// ground and within max_step_m of each other in height, and the other kUnreliable pixels to
/// Zone::unknown. Returns the tests made (one per run with traversable ends).
std::uint64_t bridge_small_gaps(const TerrainRows& terrain, const ZoneOptions& options,
                                imaging::Image<std::uint8_t>& zone);

/// Cells of the grid within `distance_m` along each axis: at least one.
int cells_within(double cell_m, double distance_m);
inline int cells_within(const GroundGrid& grid, double distance_m) {
  return cells_within(grid.cell(), distance_m);
}

/// Cells r apart along an axis such that any two points of cells at most r apart lie within
/// `distance_m` of each other along it: the largest r with (r + 1) cells <= distance_m, at least
/// one.
int cells_apart_within(double cell_m, double distance_m);
inline int cells_apart_within(const GroundGrid& grid, double distance_m) {
  return cells_apart_within(grid.cell(), distance_m);
}

/// Cells of the margin's reach: every cell whose centre lies within rover_half_width_m of an
/// obstacle cell's lies within this many cells of it along each axis.
inline int margin_cells(double cell_m, const ZoneOptions& options) {
  return static_cast<int>(std::floor(options.rover_half_width_m / cell_m));
}

/// Columns around a strip of the grid whose cells the rules of the strip's own cells read: the
/// margin's reach plus the larger of the slope's and the step window's.
int halo_columns(double cell_m, const ZoneOptions& options);

/// Work a rule did for the grid's own columns, and for its halo (done again for the strips it
/// also belongs to).
struct RuleWork {
  std::uint64_t own = 0;
  std::uint64_t halo = 0;
};

/// Highest and lowest binned elevation over the window of cells_apart_within(step_baseline_m)
/// cells around each cell, along both ground axes (-inf and +inf where the window is empty).
struct StepWindow {
  ScratchBuffer<float> highest;
  ScratchBuffer<float> lowest;
};

/// A flag (0 or 1) per cell of a grid, row by row.
using CellFlags = ScratchBuffer<std::uint8_t>;

/// The step rule's window around every cell. Every pair compared lies within the baseline: a
/// window of whole cells reaching a cell further would also compare points up to a cell beyond
/// it, and read the foot of every rock as a step a baseline away. `comparisons` counts the
/// maxima and minima taken.
StepWindow step_window(const GroundGrid& grid, const ZoneOptions& options,
                       std::pmr::memory_resource* memory, RuleWork& comparisons);

/// Whether a point of height `own` in a cell whose window is (`highest`, `lowest`) is a step:
/// some point of the window is higher, or lower, than it by more than `limit`. Float
/// differences only grow as `own` moves away, so a cell holds a step exactly when its lowest or
/// its highest point is one.
inline bool is_step(float highest, float lowest, float own, float limit) {
  return (highest - own > limit) || (own - lowest > limit);
}

/// Non-zero for the non-empty cells holding a step: their lowest or highest point is one.
CellFlags step_cells(const GroundGrid& grid, const StepWindow& window, float limit,
                     std::pmr::memory_resource* memory);

/// Non-zero for the non-empty cells whose fitted plane is steeper than max_slope_deg. `tests`
/// counts the cell means read.
CellFlags steep_cells(const GroundGrid& grid, const ZoneOptions& options,
                      std::pmr::memory_resource* memory, RuleWork& tests);

/// Non-zero for the cells whose centre lies within rover_half_width_m of the centre of a
/// cell flagged in `obstacle`; all zero when the half-width is 0. `tests` counts the cells of
/// the disc around each obstacle cell.
CellFlags near_cells(const GroundGrid& grid, const CellFlags& obstacle, const ZoneOptions& options,
                     std::pmr::memory_resource* memory, RuleWork& tests);

/// Sets `verdict` on the traversable pixels whose cell is flagged (non-zero) in `flagged`.
void mark_flagged_cells(const GroundGrid& grid, const CellFlags& flagged, Zone verdict,
                        imaging::Image<std::uint8_t>& zone);

/// Marks Zone::margin on traversable pixels whose cell lies within the rover's half-width of a
/// cell holding a step or slope pixel.
std::uint64_t grow_margin(const GroundGrid& grid, const ZoneOptions& options,
                          imaging::Image<std::uint8_t>& zone, std::pmr::memory_resource* memory);

/// What find_zones makes of a cell's traversable pixels, besides their own step test.
struct CellRules {
  StepWindow window;
  CellFlags step;
  CellFlags steep;
  CellFlags near;
};

/// The verdict of every binned pixel of the single-channel `zone` (all of them traversable)
/// whose cell is one of the grid's own: a step by its own test, else a slope where its cell is
/// steep, else a margin where its cell is near an obstacle. Other pixels keep their zone.
/// Returns the step tests made (two a pixel).
std::uint64_t judge_pixels(const GroundGrid& grid, const TerrainRows& terrain,
                           const CellRules& rules, float step_limit,
                           imaging::Image<std::uint8_t>& zone, std::pmr::memory_resource* memory);

/// The number of pixels of each zone (channel 0), values beyond the last zone counted as it.
std::array<std::uint64_t, kZoneKinds> count_zones(const imaging::Image<std::uint8_t>& zone);

} // namespace marsokhod::nav::detail
