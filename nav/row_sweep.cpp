#include "work_report.hpp"

#include "marsokhod/nav/path_planner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

constexpr float kUnreached = std::numeric_limits<float>::infinity();

// Straight ahead first, so that exact ties keep the path straight.
constexpr int kSteps[3] = {0, -1, 1};

// One row of the terrain, as the sweep reads it.
struct TerrainRow {
  const float* forward;
  const float* left;
  const float* elevation;

  TerrainRow(const TerrainPoints& terrain, int y)
      : forward(terrain.forward.row(y)), left(terrain.left.row(y)),
        elevation(terrain.elevation.row(y)) {}
};

// The weight of the edge from pixel `from` of row `below` to pixel `to` of row `here`, or +inf
// when its ends lie farther apart than weights.max_edge_m.
double edge_weight(const TerrainRow& below, int from, const TerrainRow& here, int to,
                   const EdgeWeights& weights, double max_edge_squared) {
  const double ahead = static_cast<double>(here.forward[to]) - below.forward[from];
  const double across = static_cast<double>(here.left[to]) - below.left[from];
  // Metres between neighbouring pixels: the squares can neither overflow nor underflow, so the
  // plain root is as good as std::hypot and several times cheaper.
  const double squared = ahead * ahead + across * across;
  if (squared > max_edge_squared)
    return kUnreached;
  const double climb =
      std::max(0.0, std::abs(static_cast<double>(here.elevation[to]) - below.elevation[from]) -
                        weights.flat_tolerance_m);
  return climb + weights.length_weight * std::sqrt(squared);
}

void check_sweep_arguments(const TerrainPoints& terrain, const ZoneMap& zones, PixelPoint start,
                           int first_row) {
  if (zones.width() != terrain.width() || zones.height() != terrain.height())
    throw std::invalid_argument(fmt::format("sweep_rows: {}x{} zones for a {}x{} terrain",
                                            zones.width(), zones.height(), terrain.width(),
                                            terrain.height()));
  if (!zones.zone.contains(start.x, start.y) || !zones.traversable(start.x, start.y) ||
      !terrain.known(start.x, start.y))
    throw std::invalid_argument(
        fmt::format("sweep_rows: start ({}, {}) is not a traversable pixel", start.x, start.y));
  if (first_row < 0 || first_row > start.y)
    throw std::invalid_argument(fmt::format(
        "sweep_rows: first row {} is not between 0 and the start row {}", first_row, start.y));
}

} // namespace

template <class Meter>
RowSweep sweep_rows(const TerrainPoints& terrain, const ZoneMap& zones, PixelPoint start,
                    int first_row, const EdgeWeights& weights, Meter& meter,
                    std::pmr::memory_resource* memory) {
  check_sweep_arguments(terrain, zones, start, first_row);
  const int width = terrain.width();
  RowSweep sweep{Image<float>(width, terrain.height(), 1, kUnreached, memory),
                 Image<std::int8_t>(width, terrain.height(), 1, kNoPredecessor, memory), start,
                 first_row};
  sweep.cost(start.x, start.y) = 0.0F;
  const double max_edge_squared = weights.max_edge_m * weights.max_edge_m;
  for (int y = start.y - 1; y >= first_row; --y) {
    const float* below_cost = sweep.cost.row(y + 1);
    const TerrainRow below(terrain, y + 1);
    const TerrainRow here(terrain, y);
    const std::uint8_t* zone = zones.zone.row(y);
    const std::ptrdiff_t channels = zones.zone.channels();
    float* cost = sweep.cost.row(y);
    std::int8_t* from = sweep.from.row(y);
    std::uint64_t relaxations = 0;
    for (int x = 0; x < width; ++x) {
      if (zone[x * channels] != static_cast<std::uint8_t>(Zone::traversable) ||
          !std::isfinite(here.elevation[x]))
        continue;
      double best = kUnreached;
      for (const int step : kSteps) {
        const int xb = x + step;
        if (xb < 0 || xb >= width || below_cost[xb] == kUnreached)
          continue;
        ++relaxations;
        const double candidate =
            below_cost[xb] + edge_weight(below, xb, here, x, weights, max_edge_squared);
        if (candidate < best) {
          best = candidate;
          from[x] = static_cast<std::int8_t>(step);
        }
      }
      cost[x] = static_cast<float>(best);
    }
    detail::report(meter, Work::path_relaxation, relaxations);
  }
  return sweep;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template RowSweep sweep_rows<M>(const TerrainPoints&, const ZoneMap&, PixelPoint, int,           \
                                  const EdgeWeights&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
