#include "marsokhod/nav/zones.hpp"

#include "work_report.hpp"
#include "zone_rules.hpp"

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

// Unknown where nothing was seen, nothing reliable was seen (when asked), or the point lies
// beyond the range the rules judge.
void mark_unknown(const TerrainPoints& terrain, ImageView<const std::uint8_t> reliable,
                  const ZoneOptions& options, Image<std::uint8_t>& zone) {
  const bool use_reliable = options.unreliable_is_unknown && !reliable.empty();
  const auto traversable = static_cast<std::uint8_t>(Zone::traversable);
  const auto unknown = static_cast<std::uint8_t>(Zone::unknown);
  for (int y = 0; y < terrain.height(); ++y) {
    const float* elevation = terrain.elevation.row(y);
    const float* range = terrain.range.row(y);
    std::uint8_t* out = zone.row(y);
    for (int x = 0; x < terrain.width(); ++x) {
      const bool not_seen = !std::isfinite(elevation[x]) || (use_reliable && reliable(x, y) == 0) ||
                            range[x] > options.max_range_m;
      out[x] = not_seen ? unknown : traversable;
    }
  }
}

// The pixels the rules may look at: everything not unknown.
Image<std::uint8_t> seen_pixels(const Image<std::uint8_t>& zone,
                                std::pmr::memory_resource* memory) {
  Image<std::uint8_t> seen(zone.width(), zone.height(), 1, 0, memory);
  const auto unknown = static_cast<std::uint8_t>(Zone::unknown);
  const std::ptrdiff_t channels = zone.channels();
  for (int y = 0; y < zone.height(); ++y) {
    const std::uint8_t* row = zone.row(y);
    std::uint8_t* out = seen.row(y);
    for (int x = 0; x < zone.width(); ++x)
      out[x] = row[x * channels] != unknown ? 1 : 0;
  }
  return seen;
}

void check_sizes(const TerrainPoints& terrain, int width, int height, const char* what) {
  if (width != terrain.width() || height != terrain.height())
    throw std::invalid_argument(fmt::format("{}: {}x{} does not fit the {}x{} terrain", what, width,
                                            height, terrain.width(), terrain.height()));
}

void recount(ZoneMap& zones) {
  zones.counts.fill(0);
  for (int y = 0; y < zones.height(); ++y)
    for (int x = 0; x < zones.width(); ++x)
      ++zones.counts[std::min<std::size_t>(zones.zone(x, y), kZoneKinds - 1)];
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
ZoneMap find_zones(const TerrainPoints& terrain, ImageView<const std::uint8_t> reliable,
                   const ZoneOptions& options, Meter& meter, std::pmr::memory_resource* memory) {
  validate(options);
  if (!reliable.empty())
    check_sizes(terrain, reliable.width(), reliable.height(), "find_zones: the reliability mask");
  ZoneMap map{Image<std::uint8_t>(terrain.width(), terrain.height(), 1, 0, memory), {}};
  mark_unknown(terrain, reliable, options, map.zone);
  std::uint64_t work = detail::bridge_small_gaps(terrain, options, map.zone);
  work += detail::mark_out_of_order(terrain, options, map.zone, memory);
  const detail::GroundGrid grid(terrain, seen_pixels(map.zone, memory), options.cell_m,
                                options.max_range_m, memory, work);
  work += detail::mark_steps(grid, terrain, options, map.zone, memory);
  work += detail::mark_slopes(grid, options, map.zone, memory);
  work += detail::grow_margin(grid, options, map.zone, memory);
  detail::report(meter, Work::hazard_test, work);
  recount(map);
  return map;
}

template <class Meter>
void add_margin(const TerrainPoints& terrain, const ZoneOptions& options, ZoneMap& zones,
                Meter& meter, std::pmr::memory_resource* memory) {
  validate(options);
  check_sizes(terrain, zones.width(), zones.height(), "add_margin: the zone map");
  std::uint64_t work = 0;
  const detail::GroundGrid grid(terrain, seen_pixels(zones.zone, memory), options.cell_m,
                                options.max_range_m, memory, work);
  work += detail::grow_margin(grid, options, zones.zone, memory);
  detail::report(meter, Work::hazard_test, work);
  recount(zones);
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template ZoneMap find_zones<M>(const TerrainPoints&, ImageView<const std::uint8_t>,              \
                                 const ZoneOptions&, M&, std::pmr::memory_resource*);              \
  template void add_margin<M>(const TerrainPoints&, const ZoneOptions&, ZoneMap&, M&,              \
                              std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
