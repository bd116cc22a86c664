// Bit counts that vectorise without -mpopcnt (private SIMD lane helpers of nav).
#pragma once

// Bit counts written out, because without a -mpopcnt build std::popcount becomes a library
// call per use; these compile to a few shifts and adds that vectorise.

#include <cstdint>

namespace marsokhod::nav::detail {

inline int bit_count(std::uint32_t x) {
  x = x - ((x >> 1) & 0x55555555U);
  x = (x & 0x33333333U) + ((x >> 2) & 0x33333333U);
  x = (x + (x >> 4)) & 0x0F0F0F0FU;
  x += x >> 8;
  x += x >> 16;
  return static_cast<int>(x & 0x3FU);
}

inline int bit_count(std::uint64_t x) {
  x = x - ((x >> 1) & 0x5555555555555555ULL);
  x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
  x += x >> 8;
  x += x >> 16;
  x += x >> 32;
  return static_cast<int>(x & 0x7FU);
}

} // namespace marsokhod::nav::detail
