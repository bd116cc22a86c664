// Two-lane double arithmetic for terrain and path kernels (private SIMD lane helpers).
#pragma once

// Two double lanes for the per-pixel arithmetic after the stereo (private): the terrain points
// and the path's edge weights are computed in double, and these lanes keep every operation the
// same IEEE operation the scalar code did, two pixels at a time. GCC and Clang vector
// extensions map them to SSE2 on x86-64; the square root, which has no generic form, falls back
// to std::sqrt lane by lane elsewhere.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace marsokhod::nav::detail {

using Doubles2 = double __attribute__((vector_size(16)));
using Masks2 = std::int64_t __attribute__((vector_size(16)));
using Floats2 = float __attribute__((vector_size(8)));
using Words4 = std::uint32_t __attribute__((vector_size(16)));
using Ints4 = std::int32_t __attribute__((vector_size(16)));

/// Two floats from `from`, widened exactly to double.
inline Doubles2 load_widened(const float* from) {
#ifdef __SSE2__
  // One 8-byte load and one conversion; the generic form converts lane by lane.
  return std::bit_cast<Doubles2>(
      _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(from)))));
#else
  Floats2 floats;
  std::memcpy(&floats, from, sizeof floats);
  return __builtin_convertvector(floats, Doubles2);
#endif
}

inline Doubles2 load_doubles(const double* from) {
  Doubles2 lanes;
  std::memcpy(&lanes, from, sizeof lanes);
  return lanes;
}

inline void store_floats(float* to, Floats2 lanes) {
  std::memcpy(to, &lanes, sizeof lanes);
}

/// Each lane rounded to float, as static_cast<float> rounds it.
inline Floats2 narrowed(Doubles2 lanes) {
  return __builtin_convertvector(lanes, Floats2);
}

inline Doubles2 lanes_sqrt(Doubles2 a) {
#ifdef __SSE2__
  return std::bit_cast<Doubles2>(_mm_sqrt_pd(std::bit_cast<__m128d>(a)));
#else
  return Doubles2{std::sqrt(a[0]), std::sqrt(a[1])};
#endif
}

/// std::abs lane by lane: the sign bit cleared.
inline Doubles2 lanes_abs(Doubles2 a) {
  return std::bit_cast<Doubles2>(std::bit_cast<Masks2>(a) & INT64_MAX);
}

// Masks combine, and select, through SSE2's bitwise instructions where there are: GCC 12 treats
// the plain operators on comparison results as vectors of booleans and moves them lane by lane
// through scalar registers to rebuild the masks.
#ifdef __SSE2__
inline __m128d as_m128d(Masks2 mask) {
  return std::bit_cast<__m128d>(mask);
}
#endif

/// mask ? a : b lane by lane (mask lanes 0 or -1).
inline Doubles2 select(Masks2 mask, Doubles2 a, Doubles2 b) {
#ifdef __SSE2__
  return std::bit_cast<Doubles2>(
      _mm_or_pd(_mm_and_pd(as_m128d(mask), std::bit_cast<__m128d>(a)),
                _mm_andnot_pd(as_m128d(mask), std::bit_cast<__m128d>(b))));
#else
  return std::bit_cast<Doubles2>((mask & std::bit_cast<Masks2>(a)) |
                                 (~mask & std::bit_cast<Masks2>(b)));
#endif
}

/// Lanes set in both masks.
inline Masks2 both(Masks2 a, Masks2 b) {
#ifdef __SSE2__
  return std::bit_cast<Masks2>(_mm_and_pd(as_m128d(a), as_m128d(b)));
#else
  return a & b;
#endif
}

/// Lanes set in either mask.
inline Masks2 either(Masks2 a, Masks2 b) {
#ifdef __SSE2__
  return std::bit_cast<Masks2>(_mm_or_pd(as_m128d(a), as_m128d(b)));
#else
  return a | b;
#endif
}

/// Bit i set where lane i of the mask is set: one instruction, so that a branch on a mask does
/// not move its lanes through scalar registers.
inline int lane_bits(Masks2 mask) {
#ifdef __SSE2__
  return _mm_movemask_pd(as_m128d(mask));
#else
  return (mask[0] != 0 ? 1 : 0) | (mask[1] != 0 ? 2 : 0);
#endif
}

/// Bit i set where 32-bit lane i of the mask is set.
inline int lane_bits(Ints4 mask) {
#ifdef __SSE2__
  return _mm_movemask_ps(std::bit_cast<__m128>(mask));
#else
  return (mask[0] != 0 ? 1 : 0) | (mask[1] != 0 ? 2 : 0) | (mask[2] != 0 ? 4 : 0) |
         (mask[3] != 0 ? 8 : 0);
#endif
}

/// Each lane rounded to float and back: the comparisons of float results in double lanes.
inline Doubles2 as_float(Doubles2 lanes) {
  return __builtin_convertvector(narrowed(lanes), Doubles2);
}

inline Doubles2 broadcast(double value) {
  return Doubles2{value, value};
}

} // namespace marsokhod::nav::detail
