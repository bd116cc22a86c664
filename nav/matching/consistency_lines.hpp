// The left-right check on strided lines (private to the matching and stereo rooms).
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

/// Whether left pixel x of disparity d passes the check: its right pixel x - d lies on the line
/// and the right view's disparity there (right[r], -1 for none) is within `tolerance` of d.
template <class Right>
bool agrees(int x, int d, Right right, int width, int tolerance) {
  const int r = x - d;
  const int back = static_cast<unsigned>(r) < static_cast<unsigned>(width) ? right[r] : -1;
  const int difference = back - d;
  return back >= 0 && difference <= tolerance && -difference <= tolerance;
}

/// See check_left_right(); returns the number of reliable pixels.
template <class Disparity, class Right>
int check_line(StridedLine<Disparity> left, Right right, int width, int tolerance,
               std::uint8_t* valid) {
  int reliable = 0;
  for (int x = 0; x < width; ++x) {
    const bool reliable_here = agrees(x, left[x], right, width, tolerance);
    valid[x] = reliable_here ? 255 : 0;
    reliable += reliable_here ? 1 : 0;
  }
  return reliable;
}

} // namespace marsokhod::nav::detail
