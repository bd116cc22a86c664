// Matching costs of a band: window sums of feature distances, per feature kind (private).

#include "matching/matching_cost.hpp"

#include "lanes/simd_lanes.hpp"

#include <algorithm>
#include <bit>

namespace marsokhod::nav::detail {
namespace {

using Bytes16 = std::uint8_t __attribute__((vector_size(16)));

// census3x3: the Hamming distance of each of the ten rows' bytes, then lane i sums bytes
// i .. i + 2, the rows of line i's window column.
struct ByteColumnDistance {
  static constexpr std::ptrdiff_t stride = column_stride(FeatureKind::census3x3);
  static Lanes16 apply(const std::uint16_t* left, const std::uint16_t* right) {
    const auto counts = std::bit_cast<Bytes16>(
        byte_bit_counts(load_lanes<Bits16>(left) ^ load_lanes<Bits16>(right)));
    const Bytes16 none{};
    const Bytes16 sums = counts +
                         __builtin_shufflevector(counts, none, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
                                                 12, 13, 14, 15, 16) +
                         __builtin_shufflevector(counts, none, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12,
                                                 13, 14, 15, 16, 17);
    // Bytes 0..7 interleaved with zero bytes: one unpack.
    return std::bit_cast<Lanes16>(__builtin_shufflevector(sums, none, 0, 16, 1, 17, 2, 18, 3, 19, 4,
                                                          20, 5, 21, 6, 22, 7, 23));
  }
};

// census5x5: Hamming distance summed over the words.
struct WordBitDistance {
  static constexpr std::ptrdiff_t stride = column_stride(FeatureKind::census5x5);
  static Lanes16 apply(const std::uint16_t* left, const std::uint16_t* right) {
    Bits16 bytes{};
    for (int word = 0; word < 5; ++word)
      bytes += byte_bit_counts(load_lanes<Bits16>(left + word * kBandRows) ^
                               load_lanes<Bits16>(right + word * kBandRows));
    return std::bit_cast<Lanes16>(fold_bytes(bytes));
  }
};

// rank5x5: absolute difference summed over the words.
struct RankDistance {
  static constexpr std::ptrdiff_t stride = column_stride(FeatureKind::rank5x5);
  static Lanes16 apply(const std::uint16_t* left, const std::uint16_t* right) {
    Lanes16 sum{};
    for (int word = 0; word < 3; ++word) {
      const Lanes16 difference = load_lanes<Lanes16>(left + word * kBandRows) -
                                 load_lanes<Lanes16>(right + word * kBandRows);
      sum += difference < 0 ? -difference : difference;
    }
    return sum;
  }
};

} // namespace

MatchingCost::MatchingCost(FeatureKind kind, int width, int max_disparity,
                           std::pmr::memory_resource* memory)
    : kind_(kind), width_(width), pad_(max_disparity + 2), left_(kind, -1, width + 2, memory),
      right_(kind, -pad_, width + pad_ + 1, memory) {}

void MatchingCost::load_band(const LayerFeatures& left, const LayerFeatures& right, int y0,
                             const BandLayout& layout) {
  // Only the right columns some window meets: left column x - 1 of a tile starting at x at the
  // window's largest disparity is the leftmost.
  int start = width_ + pad_ + 1;
  for (int x = 0; x < width_; x += kTileWidth)
    start = std::min(start, x - layout.first(x) - layout.cells(x) + pad_);
  left_.load(left, y0, 0);
  right_.load(right, y0, std::max(start, 0));
}

// One tile, disparity by disparity: the distances of columns first_pixel - 1 .. first_pixel +
// pixels slide through three registers, each pixel's window the sum of the last three.
template <class Distance>
void MatchingCost::tile_costs(const BandLayout& layout, int first_pixel, int pixels,
                              std::uint16_t* costs) {
  constexpr std::ptrdiff_t kStride = Distance::stride;
  const int first = layout.first(first_pixel);
  const int cells = layout.cells(first_pixel);
  const std::ptrdiff_t pixel_stride = static_cast<std::ptrdiff_t>(cells) * kBandRows;
  const std::uint16_t* tile_left = left_.column(first_pixel - 1);
  std::uint16_t* tile_out = costs + layout.offset(first_pixel) * kBandRows;
  const Lanes16 padding = broadcast16(kPaddingCost);
  for (int k = 0; k < cells; ++k) {
    const int d = first + k;
    const std::uint16_t* left = tile_left;
    const std::uint16_t* right = right_.column(first_pixel - 1 - d);
    std::uint16_t* out = tile_out + k * kBandRows;
    Lanes16 before = Distance::apply(left, right);
    Lanes16 here = Distance::apply(left + kStride, right + kStride);
    left += 2 * kStride;
    right += 2 * kStride;
    // Pixels left of x = d reach no right pixel at this disparity.
    const int reachable_from = std::clamp(d - first_pixel, 0, pixels);
    int p = 0;
    for (; p < reachable_from; ++p, left += kStride, right += kStride, out += pixel_stride) {
      const Lanes16 after = Distance::apply(left, right);
      store_lanes(out, padding);
      before = here;
      here = after;
    }
    for (; p < pixels; ++p, left += kStride, right += kStride, out += pixel_stride) {
      const Lanes16 after = Distance::apply(left, right);
      store_lanes(out, before + here + after);
      before = here;
      here = after;
    }
  }
}

template <class Distance>
std::uint64_t MatchingCost::compute_with(const BandLayout& layout, std::uint16_t* costs) {
  std::uint64_t distances = 0;
  for (int x = 0; x < width_; x += kTileWidth) {
    const int pixels = std::min(kTileWidth, width_ - x);
    tile_costs<Distance>(layout, x, pixels, costs);
    distances += static_cast<std::uint64_t>((pixels + 2) * layout.cells(x));
  }
  return distances;
}

std::uint64_t MatchingCost::compute(const BandLayout& layout, std::uint16_t* costs) {
  switch (kind_) {
  case FeatureKind::census3x3:
    return compute_with<ByteColumnDistance>(layout, costs);
  case FeatureKind::census5x5:
    return compute_with<WordBitDistance>(layout, costs);
  case FeatureKind::rank5x5:
    return compute_with<RankDistance>(layout, costs);
  }
  return 0;
}

} // namespace marsokhod::nav::detail
