#include "marsokhod/nav/consistency_check.hpp"

#include "consistency_lines.hpp"
#include "work_report.hpp"

#include <stdexcept>

namespace marsokhod::nav {

void claim_right_pixels(std::span<const int> left, std::span<const std::uint16_t> left_cost,
                        std::span<int> right, std::span<std::uint16_t> right_cost) {
  if (left_cost.size() != left.size() || right.size() != left.size() ||
      right_cost.size() != left.size())
    throw std::invalid_argument("claim_right_pixels: spans differ in length");
  detail::claim_right(detail::StridedLine<int>{left.data(), 1},
                      detail::StridedLine<std::uint16_t>{left_cost.data(), 1},
                      static_cast<int>(left.size()), right.data(), right_cost.data());
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
