#include "sliding_extremes.hpp"

#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct AsMaximum {
  float key(float value) const { return value == kInfinity ? -kInfinity : value; }
  bool keeps(float older, float newer) const { return older > newer; }
};

struct AsMinimum {
  float key(float value) const { return value; }
  bool keeps(float older, float newer) const { return older < newer; }
};

template <class Order>
std::uint64_t sliding_extreme(Strided in, int n, const int* lo, const int* hi, StridedOut out,
                              int* deque, Order order) {
  std::uint64_t comparisons = 0;
  int head = 0;
  int tail = 0;
  int next = 0;
  for (int i = 0; i < n; ++i) {
    for (; next <= hi[i]; ++next) {
      const float value = order.key(in[next]);
      // An older element no better than the newcomer can never be a window's extreme again.
      while (tail > head && !order.keeps(order.key(in[deque[tail - 1]]), value)) {
        ++comparisons;
        --tail;
      }
      ++comparisons;
      deque[tail++] = next;
    }
    while (deque[head] < lo[i])
      ++head;
    out[i] = order.key(in[deque[head]]);
  }
  return comparisons;
}

} // namespace

std::uint64_t sliding_max(Strided in, int n, const int* lo, const int* hi, StridedOut out,
                          int* deque) {
  return sliding_extreme(in, n, lo, hi, out, deque, AsMaximum{});
}

std::uint64_t sliding_min(Strided in, int n, const int* lo, const int* hi, StridedOut out,
                          int* deque) {
  return sliding_extreme(in, n, lo, hi, out, deque, AsMinimum{});
}

} // namespace marsokhod::nav::detail
