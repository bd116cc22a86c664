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

// Steps, slopes and margins on the binned pixels, all traversable so far: the rules decide per
// cell, and one pass over the pixels applies them.
std::uint64_t mark_hazards(const TerrainRows& terrain, const ZoneOptions& options,
                           const detail::GroundGrid& grid, imaging::Image<std::uint8_t>& zone,
                           std::pmr::memory_resource* memory) {
  if (grid.empty())
    return 0;
  std::uint64_t work = 0;
  const auto step_limit = static_cast<float>(options.max_step_m);
  detail::CellRules rules{
      detail::step_window(grid, options, memory, work), detail::CellFlags(memory),
      detail::steep_cells(grid, options, memory, work), detail::CellFlags(memory)};
  rules.step = detail::step_cells(grid, rules.window, step_limit, memory);
  rules.near = detail::near_cells(grid, obstacle_cells(rules, memory), options, memory, work);
  return work + detail::judge_pixels(grid, terrain, rules, step_limit, zone, memory);
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
                   const ZoneOptions& options, Meter& meter, std::pmr::memory_resource* memory) {
  validate(options);
  if (!reliable.empty())
    check_sizes(terrain, reliable.width(), reliable.height(), "find_zones: the reliability mask");
  ZoneMap map{imaging::Image<std::uint8_t>(terrain.width(), terrain.height(), 1, 0, memory), {}};
  std::uint64_t work = 0;
  if (detail::mark_unknown(terrain, reliable, options, map.zone))
    work += detail::bridge_small_gaps(terrain, options, map.zone);
  work += detail::mark_out_of_order(terrain, options, map.zone, memory);
  const detail::GroundGrid grid(terrain, map.zone, options.cell_m, options.max_range_m, memory,
                                work);
  work += mark_hazards(terrain, options, grid, map.zone, memory);
  detail::report(meter, Work::hazard_test, work);
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
  return find_zones(ResidentTerrain(terrain), reliable, options, meter, memory);
}

template <class Meter>
void add_margin(const TerrainPoints& terrain, const ZoneOptions& options, ZoneMap& zones,
                Meter& meter, std::pmr::memory_resource* memory) {
  add_margin(ResidentTerrain(terrain), options, zones, meter, memory);
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template ZoneMap find_zones<M>(const TerrainRows&, imaging::ImageView<const std::uint8_t>,       \
                                 const ZoneOptions&, M&, std::pmr::memory_resource*);              \
  template ZoneMap find_zones<M>(const TerrainPoints&, imaging::ImageView<const std::uint8_t>,     \
                                 const ZoneOptions&, M&, std::pmr::memory_resource*);              \
  template void add_margin<M>(const TerrainRows&, const ZoneOptions&, ZoneMap&, M&,                \
                              std::pmr::memory_resource*);                                         \
  template void add_margin<M>(const TerrainPoints&, const ZoneOptions&, ZoneMap&, M&,              \
                              std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
