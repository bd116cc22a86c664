// The right view's disparities of a band from its aggregated costs (private).

#include "matching/right_view.hpp"

#include "lanes/simd_lanes.hpp"

#include <algorithm>

namespace marsokhod::nav::detail {

std::uint64_t choose_right_view(const BandLayout& layout, const std::uint16_t* aggregated,
                                std::int16_t* disparity, std::int16_t* best,
                                const std::int16_t* unseen) {
  const int width = layout.width();
  const std::size_t lanes = static_cast<std::size_t>(width) * kBandRows;
  std::fill(disparity, disparity + lanes, std::int16_t{-1});
  std::fill(best, best + lanes, std::int16_t{0x7FFF});
  const Lanes16 first_seen = unseen != nullptr ? load_lanes<Lanes16>(unseen) : broadcast16(0);
  std::uint64_t examined = 0;
  // Left pixels in increasing order meet each right pixel in increasing disparity, so the
  // strict comparison keeps the smaller disparity on a tie.
  for (int x0 = 0; x0 < width; x0 += kTileWidth) {
    const int first = layout.first(x0);
    const int cells = layout.cells(x0);
    const std::uint16_t* s = aggregated + layout.offset(x0) * kBandRows;
    for (int x = x0; x < std::min(x0 + kTileWidth, width); ++x, s += cells * kBandRows) {
      const int reach = std::min(cells, x - first + 1);
      if (reach <= 0)
        continue;
      // Right pixel x - first - k, from the right end of the pixel's reach down.
      std::int16_t* held_cost = best + static_cast<std::ptrdiff_t>(x - first) * kBandRows;
      std::int16_t* held_disparity = disparity + static_cast<std::ptrdiff_t>(x - first) * kBandRows;
      Lanes16 candidate = broadcast16(first);
      const Lanes16 seen = broadcast16(x) >= first_seen;
      for (int k = 0; k < reach; ++k) {
        const Lanes16 cost = load_lanes<Lanes16>(s + k * kBandRows);
        const Lanes16 held = load_lanes<Lanes16>(held_cost - k * kBandRows);
        const Lanes16 better = seen & (cost < held);
        store_lanes(held_cost - k * kBandRows, better ? cost : held);
        const Lanes16 chosen = load_lanes<Lanes16>(held_disparity - k * kBandRows);
        store_lanes(held_disparity - k * kBandRows, better ? candidate : chosen);
        candidate += 1;
      }
      examined += static_cast<std::uint64_t>(reach);
    }
  }
  return examined;
}

} // namespace marsokhod::nav::detail
