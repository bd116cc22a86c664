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

/// Marks Zone::unknown on pixels whose ground distance contradicts their column: farther than
/// the rows above them see, or nearer than the rows below them see, by more than
/// order_tolerance (relative) plus kOrderSlack_m. Terrain seen from above has no such pixel;
/// stereo mismatches do.
std::uint64_t mark_out_of_order(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone, std::pmr::memory_resource* memory);

/// Turns back to Zone::traversable the runs of unknown pixels along a row that have a
/// (filled-in) ground point and whose two traversable ends are less than bridged_gap_m apart
/// on the ground and within max_step_m of each other in height. Returns the tests made.
std::uint64_t bridge_small_gaps(const TerrainPoints& terrain, const ZoneOptions& options,
                                Image<std::uint8_t>& zone);

/// Cells of the grid within `distance_m` along each axis: at least one.
int cells_within(const GroundGrid& grid, double distance_m);

/// Marks Zone::step on traversable pixels: some binned point within step_baseline_m along both
/// ground axes is higher or lower than the pixel's own point by more than max_step_m.
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
