#pragma once

// The left-right check on strided lines (private): the public functions of
// consistency_check.hpp use these with a stride of one, the matcher with the lane stride of a
// band, so both run the same code.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace marsokhod::nav::detail {

/// A line of values at values[x * stride].
template <class T>
struct StridedLine {
  const T* values;
  std::ptrdiff_t stride;
  T operator[](int x) const { return values[static_cast<std::ptrdiff_t>(x) * stride]; }
};

/// See check_left_right(); returns the number of reliable pixels.
template <class Disparity, class Claim>
int check_line(StridedLine<Disparity> left, const Claim* right, int width, int tolerance,
               std::uint8_t* valid) {
  int reliable = 0;
  for (int x = 0; x < width; ++x) {
    const int d = left[x];
    const int r = x - d;
    const int back = static_cast<unsigned>(r) < static_cast<unsigned>(width) ? right[r] : -1;
    const int difference = back - d;
    const bool agrees = back >= 0 && difference <= tolerance && -difference <= tolerance;
    valid[x] = agrees ? 255 : 0;
    reliable += agrees ? 1 : 0;
  }
  return reliable;
}

} // namespace marsokhod::nav::detail
