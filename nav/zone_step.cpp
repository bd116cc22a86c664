#include "zone_rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

struct Extremes {
  std::pmr::vector<float> highest;
  std::pmr::vector<float> lowest;
};

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
Extremes window_extremes(const GroundGrid& grid, int r, std::pmr::memory_resource* memory,
                         std::uint64_t& comparisons) {
  const int nx = grid.nx();
  const int ny = grid.ny();
  const auto row_of = [nx](int iy) {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx);
  };
  const std::size_t cells = row_of(ny);
  Extremes along_x{std::pmr::vector<float>(cells, memory), std::pmr::vector<float>(cells, memory)};
  for (int iy = 0; iy < ny; ++iy)
    along_row(grid.highest().data() + row_of(iy), grid.lowest().data() + row_of(iy), nx, r,
              along_x.highest.data() + row_of(iy), along_x.lowest.data() + row_of(iy));
  // Each row of the result starts as its own row along x, then takes in the rows around it.
  Extremes out{std::pmr::vector<float>(along_x.highest, memory),
               std::pmr::vector<float>(along_x.lowest, memory)};
  std::uint64_t rows_folded = 0;
  for (int iy = 0; iy < ny; ++iy) {
    float* high = out.highest.data() + row_of(iy);
    float* low = out.lowest.data() + row_of(iy);
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

int cells_within(const GroundGrid& grid, double distance_m) {
  return std::max(1, static_cast<int>(std::lround(distance_m / grid.cell())));
}

int cells_apart_within(const GroundGrid& grid, double distance_m) {
  // The relative nudge keeps 0.30 / 0.10 at 3 despite rounding.
  const double cells = std::floor(distance_m / grid.cell() * (1.0 + 1e-9));
  return std::max(1, static_cast<int>(cells) - 1);
}

std::uint64_t mark_steps(const GroundGrid& grid, const TerrainPoints& terrain,
                         const ZoneOptions& options, Image<std::uint8_t>& zone,
                         std::pmr::memory_resource* memory) {
  if (grid.empty())
    return 0;
  std::uint64_t comparisons = 0;
  const Extremes window =
      window_extremes(grid, cells_apart_within(grid, options.step_baseline_m), memory, comparisons);
  const auto limit = static_cast<float>(options.max_step_m);
  const auto traversable = static_cast<std::uint8_t>(Zone::traversable);
  const std::ptrdiff_t channels = zone.channels();
  for (int y = 0; y < zone.height(); ++y) {
    const std::int32_t* cells = grid.cells_of_row(y);
    const float* elevation = terrain.elevation.row(y);
    std::uint8_t* row = zone.row(y);
    for (int x = 0; x < zone.width(); ++x) {
      std::uint8_t& pixel = row[x * channels];
      if (cells[x] < 0 || pixel != traversable)
        continue;
      // Some point of the window is higher, or lower, than this one by more than the limit
      // (an empty window holds -inf and +inf, which the tests below reject).
      const float own = elevation[x];
      const auto i = static_cast<std::size_t>(cells[x]);
      comparisons += 2;
      if ((window.highest[i] - own > limit) || (own - window.lowest[i] > limit))
        pixel = static_cast<std::uint8_t>(Zone::step);
    }
  }
  return comparisons;
}

} // namespace marsokhod::nav::detail
