// The rounding test behind two-lane ground distances (private to the terrain room).
#pragma once

// Which lanes of a terrain point's ground distance need no std::hypot (private; elevation.cpp).

#include "lanes/path_lanes.hpp"

#include <bit>
#include <cstdint>

namespace marsokhod::nav::detail {

// Bit i set where lane i of `estimate` surely rounds to the float ground_distance() returns for
// it. That function takes the rounded root where the root scaled by 1 -+ 1e-15 rounds to the
// same float; the scaled roots lie within 10 ulps of the root, so a root in the float range
// whose 29 bits below float precision are more than kSlack ulps from a rounding midpoint
// (0x10000000) passes that test, and so does sqrt(x^2 + y^2) its range test (which the float
// range implies). Others go to ground_distance() itself: the test is conservative, never
// wrong.
inline int settled_roundings(Doubles2 estimate) {
  constexpr std::uint32_t kSlack = 16;
  constexpr std::uint32_t kLowestFloat = (1023U - 126U) << 20; // 2^-126, in the high word
  constexpr std::uint32_t kFloatBinades = 254U << 20;          // up to 2^128
  const auto words = std::bit_cast<Words4>(estimate);
  const Ints4 near_midpoint = ((words & 0x1fffffffU) - (0x10000000U - kSlack)) <= 2 * kSlack;
  const Ints4 in_float_range = (words - kLowestFloat) < kFloatBinades;
  // Lane i of the double is words 2i (low) and 2i + 1 (high).
  const int settled = ~lane_bits(near_midpoint) & (lane_bits(in_float_range) >> 1);
  return (settled & 1) | ((settled >> 1) & 2);
}

} // namespace marsokhod::nav::detail
