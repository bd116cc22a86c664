#include "right_view.hpp"

#include "simd_lanes.hpp"

#include <algorithm>

namespace marsokhod::nav::detail {

std::uint64_t choose_right_view(const BandLayout& layout, const std::uint16_t* aggregated,
                                std::int16_t* disparity, std::int16_t* best) {
  const int width = layout.width();
  const std::size_t lanes = static_cast<std::size_t>(width) * kBandRows;
  std::fill(disparity, disparity + lanes, std::int16_t{-1});
  std::fill(best, best + lanes, std::int16_t{0x7FFF});
  std::uint64_t examined = 0;
  // Left pixels in increasing order meet each right pixel in increasing disparity, so the
  // strict comparison keeps the smaller disparity on a tie.
  for (int x = 0; x < width; ++x) {
    const int first = layout.first(x);
    const int reach = std::min(layout.cells(x), x - first + 1);
    const std::uint16_t* s = aggregated + layout.offset(x) * kBandRows;
    for (int k = 0; k < reach; ++k) {
      const std::size_t r = static_cast<std::size_t>(x - first - k) * kBandRows;
      const Lanes16 cost = load_lanes<Lanes16>(s + k * kBandRows);
      const Lanes16 held = load_lanes<Lanes16>(best + r);
      const Lanes16 better = cost < held;
      store_lanes(best + r, better ? cost : held);
      const Lanes16 chosen = load_lanes<Lanes16>(disparity + r);
      store_lanes(disparity + r, better ? broadcast16(first + k) : chosen);
    }
    examined += static_cast<std::uint64_t>(std::max(reach, 0));
  }
  return examined;
}

} // namespace marsokhod::nav::detail
