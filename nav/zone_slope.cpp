#include "zone_rules.hpp"

#include <cmath>
#include <numbers>

namespace marsokhod::nav::detail {
namespace {

// The plane fitted to the 3 x 3 cells at offsets {-d, 0, d} around a cell, as the world's
// ground-truth obstacle map fits it to terrain nodes: the gradient along an axis is the
// difference of the mean heights of the two outer lines over their distance.
class PlaneFit {
public:
  PlaneFit(const GroundGrid& grid, int d) : grid_(grid), d_(d) {}

  // Squared gradient of the plane at cell (ix, iy), whose own mean is `centre`.
  double squared_gradient(int ix, int iy, double centre, std::uint64_t& tests) const {
    const double gx = gradient(ix, iy, 1, 0, centre, tests);
    const double gy = gradient(ix, iy, 0, 1, centre, tests);
    return gx * gx + gy * gy;
  }

private:
  // Gradient along (ax, ay): the outer lines are at -d and +d along it, spread along the
  // other axis. Only samples present on both lines are paired, so that a line cut short by
  // the grid's edge does not mix in the other axis's gradient; with no pair, the centre cell
  // and the sample beside it on the axis give a one-sided difference over half the distance.
  double gradient(int ix, int iy, int ax, int ay, double centre, std::uint64_t& tests) const {
    double rise = 0.0;
    int pairs = 0;
    for (const int across : {-d_, 0, d_}) {
      const float low = sample(ix, iy, ax, ay, -d_, across, tests);
      const float high = sample(ix, iy, ax, ay, d_, across, tests);
      if (std::isnan(low) || std::isnan(high))
        continue;
      rise += high - low;
      ++pairs;
    }
    const double run = d_ * grid_.cell();
    if (pairs > 0)
      return rise / pairs / (2.0 * run);
    const float high = sample(ix, iy, ax, ay, d_, 0, tests);
    if (!std::isnan(high))
      return (high - centre) / run;
    const float low = sample(ix, iy, ax, ay, -d_, 0, tests);
    if (!std::isnan(low))
      return (centre - low) / run;
    return 0.0;
  }

  // Mean height of the cell `offset` along (ax, ay) and `across` along the other axis; NaN
  // when empty or outside the grid.
  float sample(int ix, int iy, int ax, int ay, int offset, int across,
               std::uint64_t& tests) const {
    const int cx = ix + ax * offset + ay * across;
    const int cy = iy + ay * offset + ax * across;
    ++tests;
    if (!grid_.inside(cx, cy))
      return GroundGrid::kNoHeight;
    return grid_.mean(grid_.index(cx, cy));
  }

  const GroundGrid& grid_;
  int d_;
};

} // namespace

std::uint64_t mark_slopes(const GroundGrid& grid, const ZoneOptions& options,
                          Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (grid.empty())
    return 0;
  std::uint64_t tests = 0;
  const double limit = std::tan(options.max_slope_deg * std::numbers::pi / 180.0);
  const PlaneFit fit(grid, cells_within(grid, 0.5 * options.slope_baseline_m));
  std::pmr::vector<std::uint8_t> steep(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0, memory);
  for (int iy = 0; iy < grid.ny(); ++iy)
    for (int ix = 0; ix < grid.nx(); ++ix) {
      const int i = grid.index(ix, iy);
      if (grid.count(i) == 0)
        continue;
      steep[static_cast<std::size_t>(i)] =
          fit.squared_gradient(ix, iy, grid.mean(i), tests) > limit * limit ? 1 : 0;
    }
  for (int y = 0; y < zone.height(); ++y)
    for (int x = 0; x < zone.width(); ++x) {
      const int cell = grid.cell_of(x, y);
      if (cell >= 0 && steep[static_cast<std::size_t>(cell)] != 0 &&
          zone(x, y) == static_cast<std::uint8_t>(Zone::traversable))
        zone(x, y) = static_cast<std::uint8_t>(Zone::slope);
    }
  return tests;
}

} // namespace marsokhod::nav::detail
