#include "zone_rules.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace marsokhod::nav::detail {
namespace {

// The plane fitted to the 3 x 3 cells at offsets {-d, 0, d} around a cell, as the world's
// ground-truth obstacle map fits it to terrain nodes: the gradient along an axis is the
// difference of the mean heights of the two outer lines over their distance.
class PlaneFit {
public:
  PlaneFit(const GroundGrid& grid, int d, std::pmr::memory_resource* memory)
      : grid_(grid), d_(d), means_(static_cast<std::size_t>(grid.nx()) * grid.ny(), memory) {
    // Each cell's mean is read by up to twelve neighbours: divide once.
    for (std::size_t i = 0; i < means_.size(); ++i)
      means_[i] = grid.mean(static_cast<int>(i));
  }

  // Squared gradient of the plane at cell (ix, iy).
  double squared_gradient(int ix, int iy, std::uint64_t& tests) const {
    const double gx = gradient(ix, iy, 1, 0, tests);
    const double gy = gradient(ix, iy, 0, 1, tests);
    return gx * gx + gy * gy;
  }

private:
  // Gradient along (ax, ay): the outer lines are at -d and +d along it, spread along the
  // other axis. Only samples present on both lines are paired, so that a line cut short by
  // the grid's edge does not mix in the other axis's gradient. Where an outer line lies beyond
  // the grid's edge the centre line stands in for it over half the distance, as the world's
  // rule clamps its samples at the edge. An outer line that is merely empty (ground hidden
  // behind a rock, or far rows too sparse) gets no stand-in: a one-sided difference would read
  // a rock too low to be an obstacle, against the hidden ground behind it, as a slope twice as
  // steep as its flank over the baseline, and its margin would close the way around it.
  double gradient(int ix, int iy, int ax, int ay, std::uint64_t& tests) const {
    const int along = ax != 0 ? ix : iy;
    const int cells = ax != 0 ? grid_.nx() : grid_.ny();
    const int from = along - d_ >= 0 ? -d_ : 0;
    const int to = along + d_ < cells ? d_ : 0;
    if (from == to)
      return 0.0;
    const std::optional<double> rise = paired_rise(ix, iy, ax, ay, from, to, tests);
    return rise ? *rise / ((to - from) * grid_.cell()) : 0.0;
  }

  // Mean rise from the line at `from` to the line at `to` along (ax, ay) over the samples
  // present on both; nothing when no sample is.
  std::optional<double> paired_rise(int ix, int iy, int ax, int ay, int from, int to,
                                    std::uint64_t& tests) const {
    double rise = 0.0;
    int pairs = 0;
    for (const int across : {-d_, 0, d_}) {
      const float low = sample(ix, iy, ax, ay, from, across, tests);
      const float high = sample(ix, iy, ax, ay, to, across, tests);
      if (std::isnan(low) || std::isnan(high))
        continue;
      rise += high - low;
      ++pairs;
    }
    if (pairs == 0)
      return std::nullopt;
    return rise / pairs;
  }

  // Mean height of the cell `offset` along (ax, ay) and `across` along the other axis; NaN
  // when empty or outside the grid.
  float sample(int ix, int iy, int ax, int ay, int offset, int across, std::uint64_t& tests) const {
    const int cx = ix + ax * offset + ay * across;
    const int cy = iy + ay * offset + ax * across;
    ++tests;
    if (!grid_.inside(cx, cy))
      return GroundGrid::kNoHeight;
    return means_[static_cast<std::size_t>(grid_.index(cx, cy))];
  }

  const GroundGrid& grid_;
  int d_;
  std::pmr::vector<float> means_;
};

} // namespace

std::uint64_t mark_slopes(const GroundGrid& grid, const ZoneOptions& options,
                          Image<std::uint8_t>& zone, std::pmr::memory_resource* memory) {
  if (grid.empty())
    return 0;
  std::uint64_t tests = 0;
  const double limit = std::tan(options.max_slope_deg * std::numbers::pi / 180.0);
  const PlaneFit fit(grid, cells_within(grid, 0.5 * options.slope_baseline_m), memory);
  std::pmr::vector<std::uint8_t> steep(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0, memory);
  for (int iy = 0; iy < grid.ny(); ++iy)
    for (int ix = 0; ix < grid.nx(); ++ix) {
      const int i = grid.index(ix, iy);
      if (grid.count(i) == 0)
        continue;
      steep[static_cast<std::size_t>(i)] =
          fit.squared_gradient(ix, iy, tests) > limit * limit ? 1 : 0;
    }
  mark_flagged_cells(grid, steep, Zone::slope, zone);
  return tests;
}

} // namespace marsokhod::nav::detail
