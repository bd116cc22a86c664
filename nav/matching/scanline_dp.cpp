// The scan-line dynamic programme on one line, run through the band kernel in every lane.

#include "marsokhod/nav/matching/scanline_dp.hpp"

#include "matching/band_dp.hpp"
#include "matching/band_layout.hpp"

#include <cstdlib>
#include <memory_resource>
#include <stdexcept>

namespace marsokhod::nav {

std::vector<int> scanline_disparities(std::span<const std::uint16_t> costs, int width,
                                      int candidates, const DpPenalties& penalties,
                                      std::span<const std::uint8_t> intensity) {
  if (width < 1 || candidates < 1 ||
      costs.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(candidates))
    throw std::invalid_argument("scanline_disparities: costs must hold width x candidates values");
  if (!intensity.empty() && intensity.size() != static_cast<std::size_t>(width))
    throw std::invalid_argument("scanline_disparities: one grey level per pixel is needed");
  const auto penalty_ok = [](int p) { return p >= 0 && p <= kMaxPenalty; };
  if (!penalty_ok(penalties.small_step) || !penalty_ok(penalties.large_step) ||
      !penalty_ok(penalties.large_step_at_edge))
    throw std::invalid_argument("scanline_disparities: penalties must lie within 0..255");
  for (std::uint16_t cost : costs)
    if (cost > kMaxMatchingCost)
      throw std::invalid_argument("scanline_disparities: costs must lie within 0..255");
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
  detail::BandLayout layout(memory);
  const int tiles = detail::tile_count(width);
  const std::pmr::vector<int> low(static_cast<std::size_t>(tiles), 0, memory);
  const std::pmr::vector<int> high(static_cast<std::size_t>(tiles), candidates - 1, memory);
  layout.lay_out(width, {0, candidates - 1}, low, high);
  // Every lane of the band runs the same line.
  std::pmr::vector<std::uint16_t> cells(layout.total() * detail::kBandRows, 0, memory);
  std::pmr::vector<std::uint16_t> jumps(static_cast<std::size_t>(width * detail::kBandRows), 0,
                                        memory);
  for (int x = 0; x < width; ++x) {
    for (int d = 0; d < candidates; ++d)
      for (int lane = 0; lane < detail::kBandRows; ++lane)
        cells[(layout.offset(x) + static_cast<std::size_t>(d)) * detail::kBandRows +
              static_cast<std::size_t>(lane)] = costs[static_cast<std::size_t>(x * candidates + d)];
    const bool edge =
        !intensity.empty() && x > 0 &&
        std::abs(intensity[static_cast<std::size_t>(x)] -
                 intensity[static_cast<std::size_t>(x - 1)]) > penalties.edge_threshold;
    for (int lane = 0; lane < detail::kBandRows; ++lane)
      jumps[static_cast<std::size_t>(x * detail::kBandRows + lane)] =
          static_cast<std::uint16_t>(edge ? penalties.large_step_at_edge : penalties.large_step);
  }
  detail::BandDp dp(width, candidates - 1, memory);
  detail::BandChoice choice(memory);
  dp.run(layout, cells.data(), jumps.data(), penalties.small_step, choice);
  std::vector<int> disparities(static_cast<std::size_t>(width));
  for (std::size_t x = 0; x < disparities.size(); ++x)
    disparities[x] = choice.disparity[x * detail::kBandRows];
  return disparities;
}

} // namespace marsokhod::nav
