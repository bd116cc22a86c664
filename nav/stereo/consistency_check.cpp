// The left-right check and the right view of one scan line.

#include "marsokhod/nav/stereo/consistency_check.hpp"

#include "matching/band_layout.hpp"
#include "matching/consistency_lines.hpp"
#include "matching/right_view.hpp"
#include "work/work_report.hpp"

#include <algorithm>
#include <array>
#include <memory_resource>
#include <stdexcept>

namespace marsokhod::nav {

std::vector<int> right_view_disparities(std::span<const std::uint16_t> aggregated, int width,
                                        int candidates, int unseen) {
  if (width < 1 || candidates < 1 ||
      aggregated.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(candidates))
    throw std::invalid_argument(
        "right_view_disparities: aggregated must hold width x candidates values");
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
  detail::BandLayout layout(memory);
  const auto tiles = static_cast<std::size_t>(detail::tile_count(width));
  const std::pmr::vector<int> low(tiles, 0, memory);
  const std::pmr::vector<int> high(tiles, candidates - 1, memory);
  layout.lay_out(width, {0, candidates - 1}, low, high);
  // Every lane of the band holds the same line; cells beyond a pixel's reach stay unused.
  constexpr auto lanes = static_cast<std::size_t>(detail::kBandRows);
  std::pmr::vector<std::uint16_t> cells(layout.total() * lanes, 0, memory);
  for (int x = 0; x < width; ++x)
    for (int k = 0; k < layout.cells(x); ++k) {
      const std::uint16_t s =
          aggregated[static_cast<std::size_t>(x * candidates + layout.first(x) + k)];
      std::fill_n(cells.begin() + static_cast<std::ptrdiff_t>((layout.offset(x) + k) * lanes),
                  lanes, s);
    }
  std::pmr::vector<std::int16_t> right(static_cast<std::size_t>(width) * lanes, 0, memory);
  std::pmr::vector<std::int16_t> best(right.size(), 0, memory);
  std::array<std::int16_t, lanes> unseen_lanes{};
  unseen_lanes.fill(static_cast<std::int16_t>(std::clamp(unseen, 0, width)));
  detail::choose_right_view(layout, cells.data(), right.data(), best.data(), unseen_lanes.data());
  std::vector<int> out(static_cast<std::size_t>(width));
  for (std::size_t r = 0; r < out.size(); ++r)
    out[r] = right[r * lanes];
  return out;
}

template <class Meter>
int check_left_right(std::span<const int> left, std::span<const int> right, int tolerance,
                     std::span<std::uint8_t> valid, Meter& meter) {
  if (right.size() != left.size() || valid.size() < left.size())
    throw std::invalid_argument("check_left_right: left, right and valid differ in length");
  const int width = static_cast<int>(left.size());
  const int reliable = detail::check_line(detail::StridedLine<int>{left.data(), 1}, right.data(),
                                          width, tolerance, valid.data());
  detail::report(meter, Work::consistency_check, static_cast<std::uint64_t>(width));
  return reliable;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template int check_left_right<M>(std::span<const int>, std::span<const int>, int,                \
                                   std::span<std::uint8_t>, M&);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
