// The planner's row sweep: cheapest costs row by row over the pixel graph, two lanes at once.

#include "lanes/path_lanes.hpp"
#include "work/work_report.hpp"

#include "marsokhod/nav/path/path_planner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace marsokhod::nav {
namespace {

using detail::Doubles2;
using detail::Masks2;

constexpr float kUnreached = std::numeric_limits<float>::infinity();
constexpr double kUnreachedWide = std::numeric_limits<double>::infinity();

// Pixels of margin before column 0 and after the last column: the diagonal neighbours of the
// edge columns, and the second lane of an odd last column, read margin rather than a branch.
constexpr int kMargin = 1;
constexpr int kPadding = 3;

// Columns begin..end - 1 of a row.
struct Span {
  int begin = 0;
  int end = 0;
};

// One row of the terrain and its costs, widened to double once instead of once per edge. The
// margins hold finite ground and unreached costs, so their candidates never win.
struct WideRow {
  double* forward;
  double* left;
  double* elevation;
  double* cost;
};

class SweepBuffers {
public:
  SweepBuffers(int width, std::pmr::memory_resource* memory)
      : stride_(static_cast<std::size_t>(width) + kPadding), values_(8 * stride_, 0.0, memory),
        reached_(stride_, 0, memory), active_(static_cast<std::size_t>(width) + 1, 0, memory) {
    below_ = row(0);
    here_ = row(4);
    std::fill(below_.cost - kMargin, below_.cost - kMargin + stride_, kUnreachedWide);
    std::fill(here_.cost - kMargin, here_.cost - kMargin + stride_, kUnreachedWide);
  }
  WideRow& below() { return below_; }
  WideRow& here() { return here_; }
  std::uint8_t* reached() { return reached_.data() + kMargin; }
  // One byte more than the row, always 0, for the second lane of an odd last column.
  std::uint8_t* active() { return active_.data(); }
  void next_row() { std::swap(below_, here_); }

private:
  WideRow row(std::size_t first) {
    double* at = values_.data() + first * stride_ + kMargin;
    return WideRow{at, at + stride_, at + 2 * stride_, at + 3 * stride_};
  }
  std::size_t stride_;
  std::pmr::vector<double> values_;
  std::pmr::vector<std::uint8_t> reached_;
  std::pmr::vector<std::uint8_t> active_;
  WideRow below_{};
  WideRow here_{};
};

void widen_terrain(const TerrainRows::Row& points, Span columns, WideRow& row) {
  const float* forward = points.forward;
  const float* left = points.left;
  const float* elevation = points.elevation;
  for (int x = columns.begin; x < columns.end; ++x) {
    row.forward[x] = forward[x];
    row.left[x] = left[x];
    row.elevation[x] = elevation[x];
  }
}

// Keeps the costs of a finished row for the next one, and which of its pixels were reached.
void widen_costs(const float* cost, int width, WideRow& row, std::uint8_t* reached) {
  for (int x = 0; x < width; ++x) {
    row.cost[x] = cost[x];
    reached[x] = cost[x] != kUnreached ? 1 : 0;
  }
}

// The columns from the first reached pixel of a row to the last (empty when none is).
Span reached_span(const std::uint8_t* reached, Span columns) {
  Span span = columns;
  while (span.begin < span.end && reached[span.begin] == 0)
    ++span.begin;
  while (span.end > span.begin && reached[span.end - 1] == 0)
    --span.end;
  return span;
}

// Marks the traversable pixels with known ground and counts the edges into them from reached
// pixels: the edges the sweep examines. `reached` has a margin of unreached pixels.
std::uint64_t mark_active(const std::uint8_t* zone, std::ptrdiff_t channels, const float* elevation,
                          const std::uint8_t* reached, Span columns, std::uint8_t* active) {
  std::uint64_t relaxations = 0;
  for (int x = columns.begin; x < columns.end; ++x) {
    const int known = std::abs(elevation[x]) <= std::numeric_limits<float>::max() ? 1 : 0;
    const int traversable =
        zone[x * channels] == static_cast<std::uint8_t>(Zone::traversable) ? 1 : 0;
    active[x] = static_cast<std::uint8_t>(known & traversable);
    relaxations += static_cast<std::uint64_t>((known & traversable) *
                                              (reached[x - 1] + reached[x] + reached[x + 1]));
  }
  return relaxations;
}

struct LaneWeights {
  Doubles2 length_weight;
  Doubles2 flat_tolerance;
  Doubles2 max_edge_squared;

  explicit LaneWeights(const EdgeWeights& weights)
      : length_weight(detail::broadcast(weights.length_weight)),
        flat_tolerance(detail::broadcast(weights.flat_tolerance_m)),
        max_edge_squared(detail::broadcast(weights.max_edge_m * weights.max_edge_m)) {}
};

// Two lanes of pixels x, x + 1 of the row being swept.
struct HereLanes {
  Doubles2 forward;
  Doubles2 left;
  Doubles2 elevation;
};

// The edge weights from pixels xb, xb + 1 of the row below, or +inf where the ends lie farther
// apart than the limit. The plain root of the squares is as good as std::hypot between
// neighbouring pixels: they can neither overflow nor underflow.
Doubles2 edge_weights(const HereLanes& here, const WideRow& below, int xb,
                      const LaneWeights& weights) {
  const Doubles2 ahead = here.forward - detail::load_doubles(below.forward + xb);
  const Doubles2 across = here.left - detail::load_doubles(below.left + xb);
  const Doubles2 squared = ahead * ahead + across * across;
  const Doubles2 excess =
      detail::lanes_abs(here.elevation - detail::load_doubles(below.elevation + xb)) -
      weights.flat_tolerance;
  const Doubles2 climb = detail::select(Doubles2{} < excess, excess, Doubles2{});
  const Doubles2 weight = climb + weights.length_weight * detail::lanes_sqrt(squared);
  return detail::select(squared > weights.max_edge_squared, detail::broadcast(kUnreachedWide),
                        weight);
}

struct Relaxed {
  Doubles2 cost = detail::broadcast(kUnreachedWide);
  Masks2 from = Masks2{} + kNoPredecessor;

  // Straight ahead is offered first, so that exact ties keep the path straight; an unreached
  // neighbour offers +inf (or NaN beyond its ground) and never wins.
  void offer(const HereLanes& here, const WideRow& below, int x, int step,
             const LaneWeights& weights) {
    const Doubles2 candidate =
        detail::load_doubles(below.cost + x + step) + edge_weights(here, below, x + step, weights);
    const Masks2 better = candidate < cost;
    cost = detail::select(better, candidate, cost);
    from = (better & step) | (~better & from);
  }
};

// Pixels with no reached neighbour keep +inf and no predecessor, so only `columns` is relaxed;
// the second lane may lie one past it, where it finds no reached neighbour either.
void relax_row(const WideRow& here, const WideRow& below, const std::uint8_t* active, Span columns,
               int width, const LaneWeights& weights, float* cost, std::int8_t* from) {
  for (int x = columns.begin; x < columns.end; x += 2) {
    if ((active[x] | active[x + 1]) == 0)
      continue;
    const HereLanes lanes{detail::load_doubles(here.forward + x),
                          detail::load_doubles(here.left + x),
                          detail::load_doubles(here.elevation + x)};
    Relaxed relaxed;
    for (const int step : {0, -1, 1})
      relaxed.offer(lanes, below, x, step, weights);
    const detail::Floats2 narrowed = detail::narrowed(relaxed.cost);
    for (int lane = 0; lane < 2 && x + lane < width; ++lane)
      if (active[x + lane] != 0) {
        cost[x + lane] = narrowed[lane];
        from[x + lane] = static_cast<std::int8_t>(relaxed.from[lane]);
      }
  }
}

void check_sweep_arguments(const TerrainRows& terrain, const ZoneMap& zones, PixelPoint start,
                           int first_row) {
  if (zones.width() != terrain.width() || zones.height() != terrain.height())
    throw std::invalid_argument(fmt::format("sweep_rows: {}x{} zones for a {}x{} terrain",
                                            zones.width(), zones.height(), terrain.width(),
                                            terrain.height()));
  if (!zones.zone.contains(start.x, start.y) || !zones.traversable(start.x, start.y) ||
      !terrain.row(start.y).known(start.x))
    throw std::invalid_argument(
        fmt::format("sweep_rows: start ({}, {}) is not a traversable pixel", start.x, start.y));
  if (first_row < 0 || first_row > start.y)
    throw std::invalid_argument(fmt::format(
        "sweep_rows: first row {} is not between 0 and the start row {}", first_row, start.y));
}

} // namespace

template <class Meter>
RowSweep sweep_rows(const TerrainRows& terrain, const ZoneMap& zones, PixelPoint start,
                    int first_row, const EdgeWeights& weights, Meter& meter,
                    std::pmr::memory_resource* memory) {
  check_sweep_arguments(terrain, zones, start, first_row);
  const int width = terrain.width();
  RowSweep sweep{imaging::Image<float>(width, terrain.height(), 1, kUnreached, memory),
                 imaging::Image<std::int8_t>(width, terrain.height(), 1, kNoPredecessor, memory),
                 start, first_row};
  sweep.cost(start.x, start.y) = 0.0F;
  const LaneWeights lane_weights(weights);
  SweepBuffers buffers(width, memory);
  const Span whole{0, width};
  widen_terrain(terrain.row(start.y), whole, buffers.below());
  widen_costs(sweep.cost.row(start.y), width, buffers.below(), buffers.reached());
  Span reach{start.x, start.x + 1};
  // Only the columns next to reached pixels are widened and relaxed: elsewhere the buffers keep
  // older rows, whose values only ever meet unreached costs.
  for (int y = start.y - 1; y >= first_row; --y) {
    const Span columns{std::max(reach.begin - 1, 0), std::min(reach.end + 1, width)};
    const Span read{columns.begin, std::min(columns.end + 1, width)};
    const TerrainRows::Row points = terrain.row(y);
    widen_terrain(points, read, buffers.here());
    const std::uint64_t relaxations =
        mark_active(zones.zone.row(y), zones.zone.channels(), points.elevation, buffers.reached(),
                    read, buffers.active());
    relax_row(buffers.here(), buffers.below(), buffers.active(), columns, width, lane_weights,
              sweep.cost.row(y), sweep.from.row(y));
    widen_costs(sweep.cost.row(y), width, buffers.here(), buffers.reached());
    reach = reached_span(buffers.reached(), columns);
    buffers.next_row();
    detail::report(meter, Work::path_relaxation, relaxations);
  }
  return sweep;
}

template <class Meter>
RowSweep sweep_rows(const TerrainPoints& terrain, const ZoneMap& zones, PixelPoint start,
                    int first_row, const EdgeWeights& weights, Meter& meter,
                    std::pmr::memory_resource* memory) {
  return sweep_rows(ResidentTerrain(terrain), zones, start, first_row, weights, meter, memory);
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template RowSweep sweep_rows<M>(const TerrainRows&, const ZoneMap&, PixelPoint, int,             \
                                  const EdgeWeights&, M&, std::pmr::memory_resource*);             \
  template RowSweep sweep_rows<M>(const TerrainPoints&, const ZoneMap&, PixelPoint, int,           \
                                  const EdgeWeights&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
