// Prohibited zones: steps, slopes, margins and unknown ground, pixel by pixel.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <string_view>

namespace marsokhod::nav {

/// Why a pixel of the left image is or is not open to the rover.
enum class Zone : std::uint8_t {
  traversable = 0, ///< known ground within the locomotion limits
  unknown = 1,     ///< nothing reliable seen there: not traversable
  step = 2,        ///< a step over the limit within the step baseline
  slope = 3,       ///< ground steeper than the limit over the slope baseline
  margin = 4,      ///< within the rover's half-width of a step or slope
};

inline constexpr int kZoneKinds = 5;

std::string_view to_string(Zone zone);

/// The rover's locomotion limits and footprint (docs/navigation.md, "Prohibited zones").
struct ZoneOptions {
  double max_step_m = 0.30; ///< the paper: obstacles taller than 30 cm
  /// A step is sought among the points within this ground distance, along each axis. 0.20 m
  /// rather than the 0.30 m of the world's own rule: the rover sees the faces and tops of rocks,
  /// not the height field, and a wider reach read the ground beside every rock as a step a
  /// baseline away (`eval terrain --seeds 1..50`: 9.8 % of free ground prohibited at 0.30 m,
  /// 8.4 % at 0.20 m; obstacle recall 96.5 % and 95.9 %).
  double step_baseline_m = 0.20;
  double max_slope_deg = 25.0;    ///< steepest slope the six-wheel chassis climbs
  double slope_baseline_m = 0.60; ///< ground span over which a slope is measured
  /// Steps and slopes are grown by this, at each row's scale: half the chassis' width (its
  /// wheels' outer faces), so that a centre line outside the margin keeps the wheels off them.
  double rover_half_width_m = 0.5 * imaging::Chassis{}.width_m();
  /// Pixels the stereo matcher filled in (left-right check failed) count as unknown.
  bool unreliable_is_unknown = true;
  /// ...except a run of them along a row whose two reliable ends lie less than this apart on
  /// the ground and within max_step_m of each other in height: a gap narrower than a wheel
  /// cannot hide an obstacle the wheel could not span, so its filled-in points are judged like
  /// the others. 0 turns bridging off.
  double bridged_gap_m = 0.25;
  /// Ordering test of each column (0 turns it off): read from the bottom row up, the ground
  /// distances of a column never decrease for terrain seen from above; the pixels that
  /// contradict the column's longest non-decreasing run by more than this share (plus 5 cm)
  /// are unknown (docs/navigation.md, "Prohibited zones").
  double order_tolerance = 0.05;
  /// Side of the ground-grid cells the visible points are binned into for the rules.
  double cell_m = 0.10;
  /// Points farther than this are not judged: unknown.
  double max_range_m = 20.0;
};

/// Throws std::invalid_argument naming the first option that is not finite and positive
/// (the half-width may be zero; the slope must be below 90 degrees).
void validate(const ZoneOptions& options);

/// The prohibited and traversable zones of the left image (the paper's fig. 4b).
struct ZoneMap {
  imaging::Image<std::uint8_t> zone; ///< a Zone per pixel
  std::array<std::uint64_t, kZoneKinds> counts{};

  int width() const { return zone.width(); }
  int height() const { return zone.height(); }
  Zone at(int x, int y) const { return static_cast<Zone>(zone(x, y)); }
  bool traversable(int x, int y) const { return zone(x, y) == 0; }
  /// A hazard found on the terrain itself (unknown, step or slope), the margin excluded.
  bool hazard(int x, int y) const {
    const Zone z = at(x, y);
    return z != Zone::traversable && z != Zone::margin;
  }
  std::uint64_t count(Zone z) const { return counts[static_cast<std::size_t>(z)]; }
};

/// Marks every pixel of the terrain: unknown where the elevation is unknown, beyond
/// max_range_m, (with unreliable_is_unknown) where `reliable` is 0 (`reliable` may be empty)
/// outside the gaps bridged_gap_m bridges, or where the column's ordering test fails. The other
/// points are binned into a ground grid of cell_m cells (no interpolation); a pixel is a step when
/// a point within step_baseline_m along both ground axes is higher or lower than its own by more
/// than max_step_m, a slope when the plane fitted to the cells half the slope baseline around its
/// cell is steeper than max_slope_deg (an outer line with no cell present, hidden or beyond the
/// grid's edge, is left out; the centre line never stands in for it), and margin when its cell
/// lies within rover_half_width_m of a cell holding a step or slope (unknown ground is not
/// grown). Work is
/// reported as Work::hazard_test per comparison made. Throws std::invalid_argument for bad options
/// or a `reliable` mask of another size. Instantiated for NullMeter, CountingMeter and
/// DynamicMeter.
template <class Meter = NullMeter>
ZoneMap find_zones(const TerrainPoints& terrain, imaging::ImageView<const std::uint8_t> reliable,
                   const ZoneOptions& options, Meter& meter = null_meter,
                   std::pmr::memory_resource* memory = std::pmr::get_default_resource());
/// Bytes a cell of the ground grid takes at the rules' peak: its statistics (16), the step
/// window (8), the rules' flags (4) and the margin's row spreads (5).
inline constexpr std::size_t kZoneGridBytesPerCell = 33;

/// How find_zones holds the ground grid: whole (cells 0 and grid_bytes 0), or in strips of
/// columns along the forward axis, one after another, each binned again from the terrain with
/// the halo of columns its rules read around it (8 at the default options). The strips are
/// `cells` columns wide, or as wide as `grid_bytes` hold at kZoneGridBytesPerCell once the
/// grid's width across is known (at least one column). The zones are the same either way; the
/// halos' work is reported to `recompute` (if given), apart from the whole grid's work, which
/// goes to the meter as always.
struct ZoneStrips {
  int cells = 0;
  std::size_t grid_bytes = 0;
  DynamicMeter* recompute = nullptr;
};

/// find_zones on terrain read row by row (each pass over the rows reads every row once; with
/// strips, two passes per strip), the ground grid whole or in strips.
template <class Meter = NullMeter>
ZoneMap find_zones(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> reliable,
                   const ZoneOptions& options, Meter& meter = null_meter,
                   std::pmr::memory_resource* memory = std::pmr::get_default_resource(),
                   const ZoneStrips& strips = {});

/// The last stage of find_zones on its own: marks Zone::margin within rover_half_width_m of
/// the steps and slopes already in `zones` (from any source, e.g. a ground-truth obstacle map) and
/// recounts the zones. Same errors and instantiations as find_zones.
template <class Meter = NullMeter>
void add_margin(const TerrainPoints& terrain, const ZoneOptions& options, ZoneMap& zones,
                Meter& meter = null_meter,
                std::pmr::memory_resource* memory = std::pmr::get_default_resource());
template <class Meter = NullMeter>
void add_margin(const TerrainRows& terrain, const ZoneOptions& options, ZoneMap& zones,
                Meter& meter = null_meter,
                std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
