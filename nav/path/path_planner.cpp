// The safest path: start and destination choice, row sweep and path rebuilt back to start.

#include "marsokhod/nav/path/path_planner.hpp"

#include "work/work_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

void require(bool condition, const char* name, double value, const char* rule) {
  if (!condition)
    throw std::invalid_argument(fmt::format("planner option {} = {}: {}", name, value, rule));
}

double wrapped_radians(double angle) {
  return std::remainder(angle, 2.0 * std::numbers::pi);
}

// The largest float not above `limit`: for a float r, double(r) > limit exactly when
// r > float_floor(limit), so a row can be tested in float lanes.
float float_floor(double limit) {
  const auto rounded = static_cast<float>(limit);
  if (static_cast<double>(rounded) <= limit)
    return rounded;
  return std::nextafter(rounded, -std::numeric_limits<float>::infinity());
}

// The smallest float not below `limit`: for a float r, double(r) >= limit exactly when
// r >= float_ceil(limit).
float float_ceil(double limit) {
  const auto rounded = static_cast<float>(limit);
  if (static_cast<double>(rounded) >= limit)
    return rounded;
  return std::nextafter(rounded, std::numeric_limits<float>::infinity());
}

// Whether any pixel of a row lies within the start's box, whatever its zone: few rows do, and
// the test runs in float lanes without a branch.
bool row_reaches_start_box(const float* range, const float* left, int width, float max_range,
                           float max_offset) {
  int inside = 0;
  for (int x = 0; x < width; ++x) {
    const int near = range[x] > max_range ? 0 : 1;
    const int central = std::abs(left[x]) > max_offset ? 0 : 1;
    inside |= near & central;
  }
  return inside != 0;
}

bool is_hazard(const ZoneMap& zones, int x, int y) {
  const Zone zone = zones.at(x, y);
  return zone == Zone::step || zone == Zone::slope;
}

struct StartChoice {
  std::optional<PixelPoint> pixel;
  /// The nearest step or slope straight in front, when it lies before every start.
  std::optional<double> barrier_m;
};

// The nearest traversable pixel straight in front of the rover above row `below_row`; among
// equals the one nearest the heading line, then the lowest and leftmost (a fixed order, so ties
// are reproducible). None when a step or slope straight in front lies nearer: the rover would
// run over it on its way to the start.
StartChoice find_start(const TerrainRows& terrain, const ZoneMap& zones,
                       const PlannerOptions& options, int below_row) {
  const float max_range = float_floor(options.start_max_m);
  const float max_offset = float_floor(options.start_lateral_m);
  std::optional<PixelPoint> best;
  double best_range = 0.0;
  double best_offset = 0.0;
  double nearest_hazard = std::numeric_limits<double>::infinity();
  for (int y = terrain.height() - 1; y >= 0; --y) {
    const TerrainRows::Row row = terrain.row(y);
    if (!row_reaches_start_box(row.range, row.left, terrain.width(), max_range, max_offset))
      continue;
    const float* ranges = row.range;
    const float* lefts = row.left;
    for (int x = 0; x < terrain.width(); ++x) {
      if (std::abs(lefts[x]) > max_offset || ranges[x] > max_range)
        continue;
      const double range = ranges[x];
      if (is_hazard(zones, x, y))
        nearest_hazard = std::min(nearest_hazard, range);
      if (y >= below_row || !zones.traversable(x, y))
        continue;
      const double offset = std::abs(lefts[x]);
      if (!best || range < best_range || (range == best_range && offset < best_offset)) {
        best = PixelPoint{x, y};
        best_range = range;
        best_offset = offset;
      }
    }
  }
  if (best && best_range > nearest_hazard)
    return StartChoice{std::nullopt, nearest_hazard};
  return StartChoice{best, std::nullopt};
}

bool in_target_band(double range, const PlannerOptions& options) {
  return range >= options.target_min_m && range <= options.target_max_m;
}

// The highest row holding a traversable pixel of the target band (the sweep stops there).
std::optional<int> first_target_row(const TerrainRows& terrain, const ZoneMap& zones,
                                    const PlannerOptions& options, int start_row) {
  for (int y = 0; y <= start_row; ++y) {
    const float* ranges = terrain.row(y).range;
    for (int x = 0; x < terrain.width(); ++x)
      if (zones.traversable(x, y) && in_target_band(ranges[x], options))
        return y;
  }
  return std::nullopt;
}

struct Destination {
  PixelPoint pixel;
  double cost = 0.0;
  double score = 0.0;
};

// Whether any reached pixel of a row lies in the target band; most swept rows hold none, and
// the test runs in float lanes without a branch.
bool row_reaches_band(const float* cost, const float* range, int width, float nearest,
                      float farthest) {
  int inside = 0;
  for (int x = 0; x < width; ++x) {
    const int reached = std::abs(cost[x]) <= std::numeric_limits<float>::max() ? 1 : 0;
    const int beyond_nearest = range[x] >= nearest ? 1 : 0;
    const int before_farthest = range[x] <= farthest ? 1 : 0;
    inside |= reached & beyond_nearest & before_farthest;
  }
  return inside != 0;
}

// The reachable pixel of the target band with the lowest score. The heading penalty is never
// negative, so a pixel whose cost alone reaches the best score so far cannot beat it and needs
// no bearing.
std::optional<Destination> choose_destination(const TerrainRows& terrain, const RowSweep& sweep,
                                              const PlannerOptions& options) {
  const double heading = options.heading_deg * std::numbers::pi / 180.0;
  const float nearest = float_ceil(options.target_min_m);
  const float farthest = float_floor(options.target_max_m);
  std::optional<Destination> best;
  for (int y = sweep.first_row; y <= sweep.start.y; ++y) {
    const float* costs = sweep.cost.row(y);
    const TerrainRows::Row row = terrain.row(y);
    if (!row_reaches_band(costs, row.range, terrain.width(), nearest, farthest))
      continue;
    for (int x = 0; x < terrain.width(); ++x) {
      const double cost = costs[x];
      if (!std::isfinite(cost) || !in_target_band(row.range[x], options))
        continue;
      if (best && cost >= best->score)
        continue;
      const double bearing = std::atan2(row.left[x], row.forward[x]);
      const double score =
          cost + options.heading_weight * std::abs(wrapped_radians(bearing - heading));
      if (!best || score < best->score)
        best = Destination{PixelPoint{x, y}, cost, score};
    }
  }
  return best;
}

template <class Meter>
std::pmr::vector<PixelPoint> rebuild_path(const RowSweep& sweep, PixelPoint target, Meter& meter,
                                          std::pmr::memory_resource* memory) {
  std::pmr::vector<PixelPoint> path(memory);
  path.reserve(static_cast<std::size_t>(sweep.start.y - target.y + 1));
  PixelPoint at = target;
  path.push_back(at);
  while (at.y < sweep.start.y) {
    at = PixelPoint{at.x + sweep.from(at.x, at.y), at.y + 1};
    path.push_back(at);
  }
  detail::report(meter, Work::path_backtrack, path.size());
  std::reverse(path.begin(), path.end());
  return path;
}

// The highest row holding a pixel of the start box that a sweep reached: a start beyond the
// pocket the sweep explored lies above it.
int top_of_reach_in_start_box(const TerrainRows& terrain, const RowSweep& sweep,
                              const PlannerOptions& options) {
  const float max_offset = float_floor(options.start_lateral_m);
  for (int y = sweep.first_row; y < sweep.start.y; ++y) {
    const float* lefts = terrain.row(y).left;
    for (int x = 0; x < terrain.width(); ++x)
      if (std::isfinite(sweep.cost(x, y)) && std::abs(lefts[x]) <= max_offset)
        return y;
  }
  return sweep.start.y;
}

PathPlan not_found(std::string reason, std::pmr::memory_resource* memory) {
  PathPlan plan{false, std::move(reason), {}, {}, 0.0, 0.0, std::pmr::vector<PixelPoint>(memory)};
  return plan;
}

// Sweeps from the nearest start and, while no destination can be reached, from the next start
// beyond the ground the sweeps reached in front of the rover.
template <class Meter>
PathPlan plan_from_starts(const TerrainRows& terrain, const ZoneMap& zones,
                          const PlannerOptions& options, PixelPoint nearest, Meter& meter,
                          std::pmr::memory_resource* memory) {
  std::optional<PixelPoint> start = nearest;
  for (int attempt = 0; attempt < options.start_attempts && start; ++attempt) {
    const std::optional<int> first_row = first_target_row(terrain, zones, options, start->y);
    if (!first_row && attempt == 0)
      return not_found(fmt::format("no traversable ground {:.1f}-{:.1f} m away in view",
                                   options.target_min_m, options.target_max_m),
                       memory);
    if (!first_row)
      break; // farther starts see no more of the target band
    const RowSweep sweep =
        sweep_rows(terrain, zones, *start, *first_row, edge_weights(options), meter, memory);
    if (const std::optional<Destination> destination = choose_destination(terrain, sweep, options))
      return PathPlan{true,
                      {},
                      *start,
                      destination->pixel,
                      destination->cost,
                      destination->score,
                      rebuild_path(sweep, destination->pixel, meter, memory)};
    start = find_start(terrain, zones, options, top_of_reach_in_start_box(terrain, sweep, options))
                .pixel;
  }
  return not_found(fmt::format("no traversable point {:.1f}-{:.1f} m away can be reached "
                               "from the start {:.2f} m ahead",
                               options.target_min_m, options.target_max_m,
                               terrain.row(nearest.y).range[nearest.x]),
                   memory);
}

} // namespace

void validate(const PlannerOptions& options) {
  require(std::isfinite(options.heading_deg) && std::abs(options.heading_deg) <= 360.0,
          "heading_deg", options.heading_deg, "must be within -360..360");
  require(std::isfinite(options.target_min_m) && options.target_min_m > 0.0, "target_min_m",
          options.target_min_m, "must be finite and positive");
  require(std::isfinite(options.target_max_m) && options.target_max_m >= options.target_min_m,
          "target_max_m", options.target_max_m, "must be finite and at least target_min_m");
  require(std::isfinite(options.start_lateral_m) && options.start_lateral_m >= 0.0,
          "start_lateral_m", options.start_lateral_m, "must be finite and not negative");
  require(std::isfinite(options.start_max_m) && options.start_max_m > 0.0, "start_max_m",
          options.start_max_m, "must be finite and positive");
  require(std::isfinite(options.length_weight) && options.length_weight >= 0.0, "length_weight",
          options.length_weight, "must be finite and not negative");
  require(std::isfinite(options.flat_tolerance_m) && options.flat_tolerance_m >= 0.0,
          "flat_tolerance_m", options.flat_tolerance_m, "must be finite and not negative");
  require(std::isfinite(options.heading_weight) && options.heading_weight >= 0.0, "heading_weight",
          options.heading_weight, "must be finite and not negative");
  require(options.max_edge_m > 0.0, "max_edge_m", options.max_edge_m, "must be positive");
  require(options.start_attempts >= 1, "start_attempts", options.start_attempts,
          "must be at least 1");
}

template <class Meter>
PathPlan plan_path(const TerrainRows& terrain, const ZoneMap& zones, const PlannerOptions& options,
                   Meter& meter, std::pmr::memory_resource* memory) {
  validate(options);
  if (zones.width() != terrain.width() || zones.height() != terrain.height())
    throw std::invalid_argument(fmt::format("plan_path: {}x{} zones for a {}x{} terrain",
                                            zones.width(), zones.height(), terrain.width(),
                                            terrain.height()));
  const StartChoice nearest = find_start(terrain, zones, options, terrain.height());
  if (nearest.barrier_m)
    return not_found(fmt::format("a step or slope {:.2f} m straight ahead lies before every "
                                 "traversable point in front of the rover",
                                 *nearest.barrier_m),
                     memory);
  if (!nearest.pixel)
    return not_found(fmt::format("no traversable ground within {:.2f} m straight in front of "
                                 "the rover",
                                 options.start_max_m),
                     memory);
  return plan_from_starts(terrain, zones, options, *nearest.pixel, meter, memory);
}

template <class Meter>
PathPlan plan_path(const TerrainPoints& terrain, const ZoneMap& zones,
                   const PlannerOptions& options, Meter& meter, std::pmr::memory_resource* memory) {
  return plan_path(ResidentTerrain(terrain), zones, options, meter, memory);
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template PathPlan plan_path<M>(const TerrainRows&, const ZoneMap&, const PlannerOptions&, M&,    \
                                 std::pmr::memory_resource*);                                      \
  template PathPlan plan_path<M>(const TerrainPoints&, const ZoneMap&, const PlannerOptions&, M&,  \
                                 std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
