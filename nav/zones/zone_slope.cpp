// Zone rule: cells of the ground grid steeper than the slope limit.

#include "zones/zone_rules.hpp"

#include <cmath>
#include <numbers>

namespace marsokhod::nav::detail {
namespace {

// The plane fitted to the 3 x 3 cells at offsets {-d, 0, d} around a cell, as the world's
// ground-truth obstacle map fits it to terrain nodes: the gradient along an axis is the
// difference of the mean heights of the two outer lines over their distance.
//
// Only samples present on both lines are paired, so that a line cut short by the grid's edge
// does not mix in the other axis's gradient. An axis is measured only where the pair on the
// cell's own line was seen: the side pairs lie diagonally, 0.42 m from the cell at the 0.60 m
// baseline, and one of them alone, its cells holding points smeared across a rock's occluding
// edge, read level ground as steep.
//
// An outer line that is empty gets no stand-in from the centre line, whether the ground there was
// hidden (behind a rock, far rows too sparse) or lies beyond the grid's edge: the grid ends where
// the cameras stopped seeing, not where the ground ends, so its edge is unseen ground like any
// other. A one-sided difference would read a rock too low to be an obstacle, against the unseen
// ground beyond it, as a slope twice as steep as its flank over the baseline, and its margin
// would close the way around it (at the grid's near edge, the ground right in front of the
// rover).
class PlaneFit {
public:
  // The means sit in a frame of d empty cells, so that a sample across the grid's edge reads
  // as empty without a test.
  PlaneFit(const GroundGrid& grid, int d, std::pmr::memory_resource* memory)
      : grid_(grid), d_(d), stride_(grid.nx() + 2 * d),
        means_(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(grid.ny() + 2 * d),
               GroundGrid::kNoHeight, memory) {
    // Each cell's mean is read by up to twelve neighbours: divide once.
    for (int iy = 0; iy < grid.ny(); ++iy)
      for (int ix = 0; ix < grid.nx(); ++ix)
        means_[framed(ix, iy)] = grid.mean(grid.index(ix, iy));
  }

  // Squared gradient of the plane at cell (ix, iy); `tests` counts the means read.
  double squared_gradient(int ix, int iy, std::uint64_t& tests) const {
    const float* centre = means_.data() + framed(ix, iy);
    const double gx = gradient(centre, 1, stride_, tests);
    const double gy = gradient(centre, stride_, 1, tests);
    return gx * gx + gy * gy;
  }

private:
  std::size_t framed(int ix, int iy) const {
    return static_cast<std::size_t>(iy + d_) * static_cast<std::size_t>(stride_) +
           static_cast<std::size_t>(ix + d_);
  }

  // Gradient along the axis whose cells lie `step` apart in the frame (`across` along the
  // other axis); 0 where the pair on the cell's own line was not seen.
  double gradient(const float* centre, std::ptrdiff_t step, std::ptrdiff_t across,
                  std::uint64_t& tests) const {
    const float* low = centre - d_ * step;
    const float* high = centre + d_ * step;
    tests += 2;
    if (std::isnan(low[0]) || std::isnan(high[0]))
      return 0.0;
    tests += 4;
    const std::ptrdiff_t side = d_ * across;
    double rise = static_cast<double>(high[0] - low[0]);
    int pairs = 1;
    take_pair(low[-side], high[-side], rise, pairs);
    take_pair(low[side], high[side], rise, pairs);
    return rise / pairs / (2 * d_ * grid_.cell());
  }

  // Adds the rise of a pair of samples when both are present, without a branch. A sum that
  // starts at +0 is never -0, so adding +0 for a missing pair leaves it as it was.
  static void take_pair(float low, float high, double& rise, int& pairs) {
    const bool present = !std::isnan(low) & !std::isnan(high);
    rise += present ? static_cast<double>(high - low) : 0.0;
    pairs += present ? 1 : 0;
  }

  const GroundGrid& grid_;
  int d_;
  int stride_;
  std::pmr::vector<float> means_;
};

} // namespace

CellFlags steep_cells(const GroundGrid& grid, const ZoneOptions& options,
                      std::pmr::memory_resource* memory, RuleWork& tests) {
  CellFlags steep(static_cast<std::size_t>(grid.nx()) * grid.ny(), memory);
  if (grid.empty())
    return steep;
  const double limit = std::tan(options.max_slope_deg * std::numbers::pi / 180.0);
  const PlaneFit fit(grid, cells_within(grid, 0.5 * options.slope_baseline_m), memory);
  // In locals: a byte store may alias anything, and would make every member be read again.
  const double squared_limit = limit * limit;
  const std::int32_t* count = grid.counts().data();
  std::uint8_t* out = steep.data();
  const int nx = grid.nx();
  for (int iy = 0; iy < grid.ny(); ++iy)
    for (int ix = 0; ix < nx; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx) +
                            static_cast<std::size_t>(ix);
      std::uint64_t& counted = grid.owns(ix) ? tests.own : tests.halo;
      out[i] = count[i] > 0 && fit.squared_gradient(ix, iy, counted) > squared_limit ? 1 : 0;
    }
  return steep;
}

} // namespace marsokhod::nav::detail
