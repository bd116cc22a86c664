// Prohibited zones: option checks, find_zones running the rules in order, and add_margin.

#include "marsokhod/nav/zones/zones.hpp"

#include "work/work_report.hpp"
#include "zones/zone_rules.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

void require_positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument(
        fmt::format("zone option {} = {}: must be finite and positive", name, value));
}

void check_sizes(const TerrainRows& terrain, int width, int height, const char* what) {
  if (width != terrain.width() || height != terrain.height())
    throw std::invalid_argument(fmt::format("{}: {}x{} does not fit the {}x{} terrain", what, width,
                                            height, terrain.width(), terrain.height()));
}

// Obstacle cells: those holding a step or steep.
detail::CellFlags obstacle_cells(const detail::CellRules& rules,
                                 std::pmr::memory_resource* memory) {
  const std::size_t cells = rules.steep.size();
  detail::CellFlags obstacle(cells, memory);
  for (std::size_t i = 0; i < cells; ++i)
    obstacle[i] = rules.step[i] | rules.steep[i];
  return obstacle;
}

// Steps, slopes and margins on the binned pixels of the grid's own columns, all traversable so
// far: the rules decide per cell, and one pass over the pixels applies them.
detail::RuleWork judge_grid(const TerrainRows& terrain, const ZoneOptions& options,
                            const detail::GroundGrid& grid, imaging::Image<std::uint8_t>& zone,
                            std::pmr::memory_resource* memory) {
  detail::RuleWork work;
  if (grid.empty())
    return work;
  const auto step_limit = static_cast<float>(options.max_step_m);
  detail::CellRules rules{
      detail::step_window(grid, options, memory, work), detail::CellFlags(memory),
      detail::steep_cells(grid, options, memory, work), detail::CellFlags(memory)};
  rules.step = detail::step_cells(grid, rules.window, step_limit, memory);
  rules.near = detail::near_cells(grid, obstacle_cells(rules, memory), options, memory, work);
  work.own += detail::judge_pixels(grid, terrain, rules, step_limit, zone, memory);
  return work;
}

// Columns of the ordering test gathered at once within the strips' bytes (a row index and a
// distance, 8 bytes, per pixel): all of them for the whole grid.
int order_band(const ZoneStrips& strips, int height) {
  if (strips.grid_bytes == 0)
    return 0;
  const std::size_t column = static_cast<std::size_t>(std::max(height, 1)) * 8;
  return static_cast<int>(std::max<std::size_t>(1, strips.grid_bytes / column));
}

// Own columns a strip: as given, or as many as the bytes hold beside the two halos.
int strip_width(const ZoneStrips& strips, const detail::GroundLattice& lattice, int reach) {
  if (strips.cells > 0)
    return strips.cells;
  const std::size_t column_bytes =
      static_cast<std::size_t>(std::max(lattice.across.n, 1)) * kZoneGridBytesPerCell;
  const auto held = static_cast<long long>(strips.grid_bytes / column_bytes);
  return static_cast<int>(std::max(1LL, held - 2LL * reach));
}

// The whole grid at once, or strip by strip along the forward axis, each strip binned again
// with the halo of columns its rules read (that halo's work goes to `halo`).
std::uint64_t mark_hazards(const TerrainRows& terrain, const ZoneOptions& options,
                           const ZoneStrips& strips, imaging::Image<std::uint8_t>& zone,
                           std::pmr::memory_resource* memory, std::uint64_t& halo) {
  std::uint64_t work = 0;
  if (strips.cells <= 0 && strips.grid_bytes == 0) {
    const detail::GroundGrid grid(terrain, zone, options.cell_m, options.max_range_m, memory, work);
    return work + judge_grid(terrain, options, grid, zone, memory).own;
  }
  const detail::GroundLattice lattice =
      detail::ground_lattice(terrain, zone, options.cell_m, options.max_range_m, memory);
  const int columns = lattice.along.n;
  const int reach = detail::halo_columns(options.cell_m, options);
  const int width = strip_width(strips, lattice, reach);
  for (int begin = 0; begin < columns; begin += width) {
    const int end = std::min(columns, begin + width);
    const detail::GridColumns strip{std::max(0, begin - reach), std::min(columns, end + reach),
                                    begin, end};
    const detail::GroundGrid grid(terrain, zone, lattice, strip, memory, work, halo);
    const detail::RuleWork rules = judge_grid(terrain, options, grid, zone, memory);
    work += rules.own;
    halo += rules.halo;
  }
  return work;
}

} // namespace

std::string_view to_string(Zone zone) {
  switch (zone) {
  case Zone::traversable:
    return "traversable";
  case Zone::unknown:
    return "unknown";
  case Zone::step:
    return "step";
  case Zone::slope:
    return "slope";
  case Zone::margin:
    return "margin";
  }
  return "invalid";
}

void validate(const ZoneOptions& options) {
  require_positive(options.max_step_m, "max_step_m");
  require_positive(options.step_baseline_m, "step_baseline_m");
  require_positive(options.max_slope_deg, "max_slope_deg");
  require_positive(options.slope_baseline_m, "slope_baseline_m");
  if (options.max_slope_deg >= 90.0)
    throw std::invalid_argument(
        fmt::format("zone option max_slope_deg = {}: must be below 90", options.max_slope_deg));
  require_positive(options.cell_m, "cell_m");
  if (!std::isfinite(options.order_tolerance) || options.order_tolerance < 0.0 ||
      options.order_tolerance >= 1.0)
    throw std::invalid_argument(fmt::format("zone option order_tolerance = {}: must be within 0..1",
                                            options.order_tolerance));
  require_positive(options.max_range_m, "max_range_m");
  if (!std::isfinite(options.bridged_gap_m) || options.bridged_gap_m < 0.0)
    throw std::invalid_argument(fmt::format(
        "zone option bridged_gap_m = {}: must be finite and not negative", options.bridged_gap_m));
  if (!std::isfinite(options.rover_half_width_m) || options.rover_half_width_m < 0.0)
    throw std::invalid_argument(
        fmt::format("zone option rover_half_width_m = {}: must be finite and not negative",
                    options.rover_half_width_m));
}

template <class Meter>
ZoneMap find_zones(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> reliable,
                   const ZoneOptions& options, Meter& meter, std::pmr::memory_resource* memory,
                   const ZoneStrips& strips) {
  validate(options);
  if (!reliable.empty())
    check_sizes(terrain, reliable.width(), reliable.height(), "find_zones: the reliability mask");
  ZoneMap map{imaging::Image<std::uint8_t>(terrain.width(), terrain.height(), 1, 0, memory), {}};
  std::uint64_t work = 0;
  if (detail::mark_unknown(terrain, reliable, options, map.zone))
    work += detail::bridge_small_gaps(terrain, options, map.zone);
  work += detail::mark_out_of_order(terrain, options, map.zone, memory,
                                    order_band(strips, terrain.height()));
  std::uint64_t halo = 0;
  work += mark_hazards(terrain, options, strips, map.zone, memory, halo);
  detail::report(meter, Work::hazard_test, work);
  if (strips.recompute != nullptr && halo > 0)
    (*strips.recompute)(Work::hazard_test, halo);
  map.counts = detail::count_zones(map.zone);
  return map;
}

template <class Meter>
void add_margin(const TerrainRows& terrain, const ZoneOptions& options, ZoneMap& zones,
                Meter& meter, std::pmr::memory_resource* memory) {
  validate(options);
  check_sizes(terrain, zones.width(), zones.height(), "add_margin: the zone map");
  std::uint64_t work = 0;
  const detail::GroundGrid grid(terrain, zones.zone, options.cell_m, options.max_range_m, memory,
                                work);
  work += detail::grow_margin(grid, options, zones.zone, memory);
  detail::report(meter, Work::hazard_test, work);
  zones.counts = detail::count_zones(zones.zone);
}

template <class Meter>
ZoneMap find_zones(const TerrainPoints& terrain, imaging::ImageView<const std::uint8_t> reliable,
                   const ZoneOptions& options, Meter& meter, std::pmr::memory_resource* memory) {
  return find_zones(ResidentTerrain(terrain), reliable, options, meter, memory, ZoneStrips{});
}

template <class Meter>
void add_margin(const TerrainPoints& terrain, const ZoneOptions& options, ZoneMap& zones,
                Meter& meter, std::pmr::memory_resource* memory) {
  add_margin(ResidentTerrain(terrain), options, zones, meter, memory);
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template ZoneMap find_zones<M>(const TerrainRows&, imaging::ImageView<const std::uint8_t>,       \
                                 const ZoneOptions&, M&, std::pmr::memory_resource*,               \
                                 const ZoneStrips&);                                               \
  template ZoneMap find_zones<M>(const TerrainPoints&, imaging::ImageView<const std::uint8_t>,     \
                                 const ZoneOptions&, M&, std::pmr::memory_resource*);              \
  template void add_margin<M>(const TerrainRows&, const ZoneOptions&, ZoneMap&, M&,                \
                              std::pmr::memory_resource*);                                         \
  template void add_margin<M>(const TerrainPoints&, const ZoneOptions&, ZoneMap&, M&,              \
                              std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
