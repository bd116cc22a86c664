// Fixed-width SIMD lanes for the stereo matcher's inner loops (private lane helpers).
#pragma once

// Fixed-width lanes for the inner loops of the stereo matcher (private). GCC and Clang vector
// extensions: one 16-byte register of 8 16-bit or 4 32-bit lanes, which the compiler maps to
// SSE2 on x86-64 (or NEON, or plain scalar code where there is no vector unit). Loads and
// stores go through memcpy, so they need no alignment and break no aliasing rule.

#include <bit>
#include <cstdint>
#include <cstring>

#ifdef __SSE__
#include <xmmintrin.h>
#endif

namespace marsokhod::nav::detail {

using Lanes16 = std::int16_t __attribute__((vector_size(16)));
using Bits16 = std::uint16_t __attribute__((vector_size(16)));
using Lanes32 = std::uint32_t __attribute__((vector_size(16)));
using Floats4 = float __attribute__((vector_size(16)));
using Ints4 = std::int32_t __attribute__((vector_size(16)));
inline constexpr int kLanes16 = 8;
inline constexpr int kLanes32 = 4;
inline constexpr int kFloatLanes = 4;

template <class Lanes, class T>
inline Lanes load_lanes(const T* from) {
  Lanes lanes;
  std::memcpy(&lanes, from, sizeof lanes);
  return lanes;
}

template <class Lanes, class T>
inline void store_lanes(T* to, Lanes lanes) {
  std::memcpy(to, &lanes, sizeof lanes);
}

inline Lanes16 broadcast16(int value) {
  return Lanes16{} + static_cast<std::int16_t>(value);
}
inline Lanes32 broadcast32(std::uint32_t value) {
  return Lanes32{} + value;
}

inline Lanes16 lanes_min(Lanes16 a, Lanes16 b) {
  return a < b ? a : b;
}
inline Lanes16 lanes_max(Lanes16 a, Lanes16 b) {
  return a < b ? b : a;
}

/// a < b ? a : b and a < b ? b : a lane by lane. The vector conditional compiles to a compare
/// and three logic instructions; SSE's minps (a < b ? a : b) and maxps (b < a ? b : a, so with
/// the operands swapped) give the same lanes, signed zeros and NaNs included, in one.
inline Floats4 floats_min(Floats4 a, Floats4 b) {
#ifdef __SSE__
  return std::bit_cast<Floats4>(_mm_min_ps(std::bit_cast<__m128>(a), std::bit_cast<__m128>(b)));
#else
  return a < b ? a : b;
#endif
}
inline Floats4 floats_max(Floats4 a, Floats4 b) {
#ifdef __SSE__
  return std::bit_cast<Floats4>(_mm_max_ps(std::bit_cast<__m128>(b), std::bit_cast<__m128>(a)));
#else
  return a < b ? b : a;
#endif
}

/// Lanes 0..3 or 4..7 as floats: each 16-bit lane is doubled into a 32-bit lane and shifted
/// back with its sign, which SSE2 does in two instructions (a direct conversion would go lane
/// by lane through scalar registers).
inline Floats4 low_floats(Lanes16 v) {
  const auto doubled = std::bit_cast<Ints4>(__builtin_shufflevector(v, v, 0, 0, 1, 1, 2, 2, 3, 3));
  return __builtin_convertvector(doubled >> 16, Floats4);
}
inline Floats4 high_floats(Lanes16 v) {
  const auto doubled = std::bit_cast<Ints4>(__builtin_shufflevector(v, v, 4, 4, 5, 5, 6, 6, 7, 7));
  return __builtin_convertvector(doubled >> 16, Floats4);
}

/// Eight bytes from `from` widened to 16-bit lanes.
inline Lanes16 widen_bytes(const std::uint8_t* from) {
  using Bytes16 = std::uint8_t __attribute__((vector_size(16)));
  Bytes16 bytes{};
  std::memcpy(&bytes, from, 8);
  // Interleaved with zero bytes: one unpack.
  return std::bit_cast<Lanes16>(__builtin_shufflevector(bytes, Bytes16{}, 0, 16, 1, 17, 2, 18, 3,
                                                        19, 4, 20, 5, 21, 6, 22, 7, 23));
}

/// Transposes an 8 x 8 block: afterwards rows[i][j] holds what rows[j][i] held. Three rounds
/// of interleaving (16-, 32- and 64-bit units), as SSE2 does it in 24 unpack instructions.
inline void transpose8x8(Lanes16 (&rows)[8]) {
  Lanes16 pairs[8];
  for (int i = 0; i < 8; i += 2) {
    pairs[i] = __builtin_shufflevector(rows[i], rows[i + 1], 0, 8, 1, 9, 2, 10, 3, 11);
    pairs[i + 1] = __builtin_shufflevector(rows[i], rows[i + 1], 4, 12, 5, 13, 6, 14, 7, 15);
  }
  Lanes16 quads[8];
  for (int i = 0; i < 8; i += 4)
    for (int half = 0; half < 2; ++half) {
      const Lanes16 a = pairs[i + half];
      const Lanes16 b = pairs[i + half + 2];
      quads[i + 2 * half] = __builtin_shufflevector(a, b, 0, 1, 8, 9, 2, 3, 10, 11);
      quads[i + 2 * half + 1] = __builtin_shufflevector(a, b, 4, 5, 12, 13, 6, 7, 14, 15);
    }
  for (int i = 0; i < 4; ++i) {
    rows[2 * i] = __builtin_shufflevector(quads[i], quads[i + 4], 0, 1, 2, 3, 8, 9, 10, 11);
    rows[2 * i + 1] = __builtin_shufflevector(quads[i], quads[i + 4], 4, 5, 6, 7, 12, 13, 14, 15);
  }
}

/// Lanes 0..3 or 4..7 of a mask (0 or -1 per lane) as a mask of 32-bit lanes.
inline Ints4 low_mask(Lanes16 v) {
  return std::bit_cast<Ints4>(__builtin_shufflevector(v, v, 0, 0, 1, 1, 2, 2, 3, 3));
}
inline Ints4 high_mask(Lanes16 v) {
  return std::bit_cast<Ints4>(__builtin_shufflevector(v, v, 4, 4, 5, 5, 6, 6, 7, 7));
}

/// The smallest of the 8 lanes, in three halving steps.
inline int smallest_lane(Lanes16 v) {
  v = lanes_min(v, __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3));
  v = lanes_min(v, __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5));
  v = lanes_min(v, __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6));
  return v[0];
}

/// Set bits of each byte of each 16-bit lane (at most 8 per byte), by the shift-and-add tree;
/// sums of several of these still fit a byte, and fold_bytes() finishes the count.
inline Bits16 byte_bit_counts(Bits16 x) {
  x = x - ((x >> 1) & 0x5555);
  x = (x & 0x3333) + ((x >> 2) & 0x3333);
  return (x + (x >> 4)) & 0x0F0F;
}

/// Adds the two bytes of each 16-bit lane.
inline Bits16 fold_bytes(Bits16 x) {
  return (x + (x >> 8)) & 0x00FF;
}

/// Set bits of each 32-bit lane (at most 32), by the shift-and-add tree.
inline Lanes32 lane_bit_counts(Lanes32 x) {
  x = x - ((x >> 1) & 0x55555555U);
  x = (x & 0x33333333U) + ((x >> 2) & 0x33333333U);
  x = (x + (x >> 4)) & 0x0F0F0F0FU;
  x = x + (x >> 8);
  x = x + (x >> 16);
  return x & 0x3FU;
}

} // namespace marsokhod::nav::detail
