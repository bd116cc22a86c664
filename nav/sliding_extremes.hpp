#pragma once

// Running maximum and minimum over windows that slide one way (monotone deque, amortised two
// comparisons per element whatever the window length): the primitive of the prohibited-zone
// tests, whose windows change size from row to row with the perspective scale.

#include <cstddef>
#include <cstdint>

namespace marsokhod::nav::detail {

/// A sequence of n floats `stride` elements apart.
struct Strided {
  const float* data = nullptr;
  std::ptrdiff_t stride = 1;
  float operator[](int i) const { return data[i * stride]; }
};

/// The same for output.
struct StridedOut {
  float* data = nullptr;
  std::ptrdiff_t stride = 1;
  float& operator[](int i) const { return data[i * stride]; }
};

/// out[i] = max of in[lo[i] .. hi[i]] for i in 0..n-1, where lo and hi never decrease and
/// lo[i] <= hi[i]. +inf inputs (unknown elevations) count as -inf, so a window with nothing
/// known gives -inf. `deque` holds n ints. Returns the comparisons made.
std::uint64_t sliding_max(Strided in, int n, const int* lo, const int* hi, StridedOut out,
                          int* deque);

/// out[i] = min of in[lo[i] .. hi[i]]; +inf inputs stay +inf (unknown never wins a minimum).
std::uint64_t sliding_min(Strided in, int n, const int* lo, const int* hi, StridedOut out,
                          int* deque);

} // namespace marsokhod::nav::detail
