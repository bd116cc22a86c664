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

// The edge's weight, or +inf when its ends lie farther apart than weights.max_edge_m.
double edge_weight(const TerrainPoints& terrain, int x_from, int y_from, int x_to, int y_to,
                   const EdgeWeights& weights) {
  const double run =
      std::hypot(static_cast<double>(terrain.forward(x_to, y_to)) - terrain.forward(x_from, y_from),
                 static_cast<double>(terrain.left(x_to, y_to)) - terrain.left(x_from, y_from));
  if (run > weights.max_edge_m)
    return kUnreached;
  const double climb = std::max(0.0, std::abs(static_cast<double>(terrain.elevation(x_to, y_to)) -
                                              terrain.elevation(x_from, y_from)) -
                                         weights.flat_tolerance_m);
  return climb + weights.length_weight * run;
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
  for (int y = start.y - 1; y >= first_row; --y) {
    const float* below = sweep.cost.row(y + 1);
    float* cost = sweep.cost.row(y);
    std::int8_t* from = sweep.from.row(y);
    std::uint64_t relaxations = 0;
    for (int x = 0; x < width; ++x) {
      if (!zones.traversable(x, y) || !terrain.known(x, y))
        continue;
      double best = kUnreached;
      for (const int step : kSteps) {
        const int xb = x + step;
        if (xb < 0 || xb >= width || below[xb] == kUnreached)
          continue;
        ++relaxations;
        const double candidate = below[xb] + edge_weight(terrain, xb, y + 1, x, y, weights);
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
