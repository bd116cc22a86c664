// Which pixels the ground grid bins, and the bounds of their points (private to the zones).

#include "zones/zone_bounds.hpp"

#include "zones/zone_bytes.hpp"

#include "marsokhod/nav/zones/zones.hpp"

#include <cmath>
#include <cstring>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace marsokhod::nav::detail {
namespace {

bool binned_pixel(std::uint8_t zone, float elevation, float range, float max_range) {
  return zone != kUnknownZone && std::isfinite(elevation) && range <= max_range;
}

// Pixels [from, width) of a row, one at a time.
void mark_tail(const std::uint8_t* zone, const float* elevation, const float* range,
               const float* forward, const float* left, float max_range, int from, int width,
               std::int32_t* binned, GroundBounds& bounds) {
  for (int x = from; x < width; ++x) {
    const bool in = binned_pixel(zone[x], elevation[x], range[x], max_range);
    binned[x] = in ? kBinned : kNotBinned;
    if (in)
      bounds.take(forward[x], left[x]);
  }
}

#ifdef __SSE2__
// The bounds over four lanes: a pixel that is not binned stands as +inf to the minima and -inf
// to the maxima. The operands of minps and maxps are ordered so that a NaN point keeps the bound.
class BoundLanes {
public:
  void take(__m128 in, __m128 x, __m128 y) {
    min_x_ = _mm_min_ps(select(in, x, infinity_), min_x_);
    max_x_ = _mm_max_ps(select(in, x, minus_infinity_), max_x_);
    min_y_ = _mm_min_ps(select(in, y, infinity_), min_y_);
    max_y_ = _mm_max_ps(select(in, y, minus_infinity_), max_y_);
  }
  GroundBounds fold() const {
    alignas(16) float lanes[4][4];
    _mm_store_ps(lanes[0], min_x_);
    _mm_store_ps(lanes[1], max_x_);
    _mm_store_ps(lanes[2], min_y_);
    _mm_store_ps(lanes[3], max_y_);
    GroundBounds b;
    for (int lane = 0; lane < 4; ++lane)
      b.take(GroundBounds{lanes[0][lane], lanes[1][lane], lanes[2][lane], lanes[3][lane]});
    return b;
  }

private:
  static __m128 select(__m128 mask, __m128 value, __m128 otherwise) {
    return _mm_or_ps(_mm_and_ps(mask, value), _mm_andnot_ps(mask, otherwise));
  }

  __m128 infinity_ = _mm_set1_ps(kInfinity);
  __m128 minus_infinity_ = _mm_set1_ps(-kInfinity);
  __m128 min_x_ = infinity_;
  __m128 max_x_ = minus_infinity_;
  __m128 min_y_ = infinity_;
  __m128 max_y_ = minus_infinity_;
};

// Four pixels' bytes widened to 32-bit lanes.
__m128i widen_four(const std::uint8_t* bytes) {
  std::int32_t four = 0;
  std::memcpy(&four, bytes, sizeof four);
  const __m128i zero = _mm_setzero_si128();
  return _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(four), zero), zero);
}
#endif

} // namespace

void mark_binned_row(const std::uint8_t* zone, const float* elevation, const float* range,
                     float max_range, int width, std::int32_t* binned) {
  for (int x = 0; x < width; ++x)
    binned[x] = binned_pixel(zone[x], elevation[x], range[x], max_range) ? kBinned : kNotBinned;
}

GroundBounds mark_binned(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> zone,
                         float max_range, std::int32_t* binned, std::ptrdiff_t row_stride) {
  const int width = terrain.width();
  GroundBounds bounds;
#ifdef __SSE2__
  BoundLanes lanes;
  const __m128i unknown = _mm_set1_epi32(kUnknownZone);
  // A finite float's magnitude is at most the largest one; NaN and infinities fail.
  const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
  const __m128 largest = _mm_set1_ps(std::numeric_limits<float>::max());
  const __m128 range_limit = _mm_set1_ps(max_range);
#endif
  for (int y = 0; y < terrain.height(); ++y) {
    const std::uint8_t* judged = zone.row(y);
    const TerrainRows::Row row = terrain.row(y);
    const float* elevation = row.elevation;
    const float* range = row.range;
    const float* forward = row.forward;
    const float* left = row.left;
    std::int32_t* out = binned + y * row_stride;
    int x = 0;
#ifdef __SSE2__
    for (; x + 4 <= width; x += 4) {
      const __m128 unknown_pixel =
          _mm_castsi128_ps(_mm_cmpeq_epi32(widen_four(judged + x), unknown));
      const __m128 finite =
          _mm_cmple_ps(_mm_and_ps(_mm_loadu_ps(elevation + x), magnitude), largest);
      const __m128 in_range = _mm_cmple_ps(_mm_loadu_ps(range + x), range_limit);
      const __m128 in = _mm_andnot_ps(unknown_pixel, _mm_and_ps(finite, in_range));
      // kBinned is 0 and kNotBinned -1: the complement of the mask.
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + x),
                       _mm_xor_si128(_mm_castps_si128(in), _mm_set1_epi32(-1)));
      lanes.take(in, _mm_loadu_ps(forward + x), _mm_loadu_ps(left + x));
    }
#endif
    mark_tail(judged, elevation, range, forward, left, max_range, x, width, out, bounds);
  }
#ifdef __SSE2__
  bounds.take(lanes.fold());
#endif
  return bounds;
}

} // namespace marsokhod::nav::detail
