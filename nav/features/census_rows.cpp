// The 3x3 census transform of one image row, sixteen pixels at a time (private).

#include "features/census_rows.hpp"

#include <bit>
#include <cstring>

namespace marsokhod::nav::detail {
namespace {

using Bytes16 = std::uint8_t __attribute__((vector_size(16)));
constexpr int kBytes = 16;

template <class T>
T load_at(const std::uint8_t* from) {
  if constexpr (sizeof(T) == 1) {
    return *from;
  } else {
    T value;
    std::memcpy(&value, from, sizeof value);
    return value;
  }
}

// `bit` where neighbour n is not darker than centre c, for one pixel or 16 at once: n >= c is
// one saturating subtraction and one comparison in SSE2, n < c two comparisons.
template <class T>
T not_darker(T n, T c, std::uint8_t bit) {
  if constexpr (sizeof(T) == 1)
    return static_cast<T>(n >= c ? bit : 0);
  else
    return std::bit_cast<T>(n >= c) & bit;
}

// The eight bits cover the byte, so the darker neighbours are the complement of the others.
template <class T>
T census_at(const std::uint8_t* above, const std::uint8_t* here, const std::uint8_t* below, int x) {
  const T c = load_at<T>(here + x);
  const T others =
      not_darker(load_at<T>(above + x - 1), c, 0x80) | not_darker(load_at<T>(above + x), c, 0x40) |
      not_darker(load_at<T>(above + x + 1), c, 0x20) |
      not_darker(load_at<T>(here + x - 1), c, 0x10) |
      not_darker(load_at<T>(here + x + 1), c, 0x08) |
      not_darker(load_at<T>(below + x - 1), c, 0x04) | not_darker(load_at<T>(below + x), c, 0x02) |
      not_darker(load_at<T>(below + x + 1), c, 0x01);
  return static_cast<T>(~others);
}

} // namespace

void census3x3_row(const std::uint8_t* above, const std::uint8_t* here, const std::uint8_t* below,
                   int width, std::uint8_t* out) {
  int x = 0;
  // A block reads up to x + 16, the padding entry at `width` included.
  for (; x + kBytes <= width; x += kBytes) {
    const Bytes16 bits = census_at<Bytes16>(above, here, below, x);
    std::memcpy(out + x, &bits, sizeof bits);
  }
  for (; x < width; ++x)
    out[x] = census_at<std::uint8_t>(above, here, below, x);
}

} // namespace marsokhod::nav::detail
