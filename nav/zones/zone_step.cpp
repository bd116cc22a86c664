// Zone rule: cells of the ground grid with a step over the limit within the step baseline.

#include "zones/zone_rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

// out[i] = max (min) of in[i - r .. i + r] clipped to 0..n-1: the row itself and then, for each
// offset, two whole-row passes that the compiler turns into vector maxima. Windows are a few
// cells wide, so the direct sum of 2r + 1 rows beats any amortised scheme.
void along_row(const float* high_in, const float* low_in, int n, int r, float* high_out,
               float* low_out) {
  std::copy_n(high_in, n, high_out);
  std::copy_n(low_in, n, low_out);
  for (int k = 1; k <= r && k < n; ++k) {
    for (int i = 0; i + k < n; ++i) {
      high_out[i] = std::max(high_out[i], high_in[i + k]);
      low_out[i] = std::min(low_out[i], low_in[i + k]);
    }
    for (int i = k; i < n; ++i) {
      high_out[i] = std::max(high_out[i], high_in[i - k]);
      low_out[i] = std::min(low_out[i], low_in[i - k]);
    }
  }
}

// The extremes over the square window of +-r cells, separably: along x within each row, then
// across the rows iy - r .. iy + r. Empty cells hold -inf for the maximum and +inf for the
// minimum, so an empty window gives values that no step test passes.
StepWindow window_extremes(const GroundGrid& grid, int r, std::pmr::memory_resource* memory,
                           std::uint64_t& comparisons) {
  const int nx = grid.nx();
  const int ny = grid.ny();
  const auto row_of = [nx](int iy) {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx);
  };
  const std::size_t cells = row_of(ny);
  StepWindow along_x{ScratchBuffer<float>(cells, memory), ScratchBuffer<float>(cells, memory)};
  for (int iy = 0; iy < ny; ++iy)
    along_row(grid.highest().data() + row_of(iy), grid.lowest().data() + row_of(iy), nx, r,
              along_x.highest.data() + row_of(iy), along_x.lowest.data() + row_of(iy));
  StepWindow out{ScratchBuffer<float>(cells, memory), ScratchBuffer<float>(cells, memory)};
  std::uint64_t rows_folded = 0;
  for (int iy = 0; iy < ny; ++iy) {
    float* high = out.highest.data() + row_of(iy);
    float* low = out.lowest.data() + row_of(iy);
    // Each row of the result starts as its own row along x, then takes in the rows around it.
    std::copy_n(along_x.highest.data() + row_of(iy), nx, high);
    std::copy_n(along_x.lowest.data() + row_of(iy), nx, low);
    for (int other = std::max(0, iy - r); other <= std::min(ny - 1, iy + r); ++other) {
      if (other == iy)
        continue;
      const float* high_in = along_x.highest.data() + row_of(other);
      const float* low_in = along_x.lowest.data() + row_of(other);
      for (int ix = 0; ix < nx; ++ix) {
        high[ix] = std::max(high[ix], high_in[ix]);
        low[ix] = std::min(low[ix], low_in[ix]);
      }
      ++rows_folded;
    }
  }
  // Two comparisons (maximum and minimum) per cell and offset along x, per cell and row across.
  comparisons += 2 * (cells * static_cast<std::uint64_t>(2 * r) +
                      rows_folded * static_cast<std::uint64_t>(nx));
  return out;
}

} // namespace

int cells_within(double cell_m, double distance_m) {
  return std::max(1, static_cast<int>(std::lround(distance_m / cell_m)));
}

int cells_apart_within(double cell_m, double distance_m) {
  // The relative nudge keeps 0.30 / 0.10 at 3 despite rounding.
  const double cells = std::floor(distance_m / cell_m * (1.0 + 1e-9));
  return std::max(1, static_cast<int>(cells) - 1);
}

int halo_columns(double cell_m, const ZoneOptions& options) {
  return margin_cells(cell_m, options) +
         std::max(cells_within(cell_m, 0.5 * options.slope_baseline_m),
                  cells_apart_within(cell_m, options.step_baseline_m));
}

StepWindow step_window(const GroundGrid& grid, const ZoneOptions& options,
                       std::pmr::memory_resource* memory, RuleWork& comparisons) {
  std::uint64_t all = 0;
  StepWindow window =
      window_extremes(grid, cells_apart_within(grid, options.step_baseline_m), memory, all);
  // The same comparisons for every column: the own columns' share is exact.
  const auto own = static_cast<std::uint64_t>(grid.own_end() - grid.own_begin());
  const std::uint64_t own_share =
      grid.nx() > 0 ? all / static_cast<std::uint64_t>(grid.nx()) * own : 0;
  comparisons.own += own_share;
  comparisons.halo += all - own_share;
  return window;
}

CellFlags step_cells(const GroundGrid& grid, const StepWindow& window, float limit,
                     std::pmr::memory_resource* memory) {
  const std::size_t cells = window.highest.size();
  CellFlags step(cells, memory);
  const float* high = window.highest.data();
  const float* low = window.lowest.data();
  const float* own_high = grid.highest().data();
  const float* own_low = grid.lowest().data();
  const std::int32_t* count = grid.counts().data();
  std::uint8_t* out = step.data();
  // Branch-free (& and | rather than && and ||), so that the loop vectorises. An empty cell's
  // own extremes (-inf highest, +inf lowest) would read as steps: its count rules it out.
  for (std::size_t i = 0; i < cells; ++i) {
    const bool at_low = (high[i] - own_low[i] > limit) | (own_low[i] - low[i] > limit);
    const bool at_high = (high[i] - own_high[i] > limit) | (own_high[i] - low[i] > limit);
    out[i] = (count[i] > 0) & (at_low | at_high) ? 1 : 0;
  }
  return step;
}

} // namespace marsokhod::nav::detail
