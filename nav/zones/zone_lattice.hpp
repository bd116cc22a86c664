// The ground grid's cells along one axis (private to the zones' ground grid).
#pragma once

// The ground grid's cells along one axis (private to ground_grid.cpp), for one point or, with
// SSE2, four at a time with the very same double arithmetic.

#include <algorithm>
#include <cstdint>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace marsokhod::nav::detail {

/// n cells of `cell` metres from `origin` along one ground axis.
struct LatticeAxis {
  double origin;
  double cell;
  int n;

  /// Offsets are never negative beyond rounding: truncation is the floor once clamped.
  int cell_of(float at) const {
    return std::clamp(static_cast<int>((at - origin) / cell), 0, n - 1);
  }
};

/// The ground grid's lattice: `along` the forward axis (the grid's columns), `across` the
/// lateral one (its rows), `origin`, a binned point that masked lanes stand in for, and the
/// range beyond which points are not binned.
struct GroundLattice {
  LatticeAxis along{0.0, 0.1, 0};
  LatticeAxis across{0.0, 0.1, 0};
  float origin[2] = {0.0F, 0.0F};
  float max_range = 0.0F;

  bool empty() const { return along.n == 0 || across.n == 0; }
};

#ifdef __SSE2__
/// cell_of for four points: each widened to a double, offset, divided and truncated as one
/// would be (a NaN truncates to INT_MIN in both and is clamped to cell 0).
class LatticeLanes {
public:
  explicit LatticeLanes(const LatticeAxis& axis)
      : origin_(_mm_set1_pd(axis.origin)), cell_(_mm_set1_pd(axis.cell)),
        last_(_mm_set1_epi32(axis.n - 1)) {}

  __m128i cells_of(__m128 at) const {
    const __m128d low = _mm_div_pd(_mm_sub_pd(_mm_cvtps_pd(at), origin_), cell_);
    const __m128d high =
        _mm_div_pd(_mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(at, at)), origin_), cell_);
    const __m128i cells = _mm_unpacklo_epi64(_mm_cvttpd_epi32(low), _mm_cvttpd_epi32(high));
    const __m128i above = _mm_and_si128(cells, _mm_cmpgt_epi32(cells, _mm_setzero_si128()));
    const __m128i over = _mm_cmpgt_epi32(above, last_);
    return _mm_or_si128(_mm_andnot_si128(over, above), _mm_and_si128(over, last_));
  }

private:
  __m128d origin_;
  __m128d cell_;
  __m128i last_;
};

/// a * b lane by lane for products that fit 32 bits: SSE2 multiplies only even lanes.
inline __m128i multiply_lanes(__m128i a, __m128i b) {
  const __m128i even = _mm_mul_epu32(a, b);
  const __m128i odd = _mm_mul_epu32(_mm_srli_epi64(a, 32), _mm_srli_epi64(b, 32));
  return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, _MM_SHUFFLE(0, 0, 2, 0)),
                            _mm_shuffle_epi32(odd, _MM_SHUFFLE(0, 0, 2, 0)));
}
#endif

} // namespace marsokhod::nav::detail
