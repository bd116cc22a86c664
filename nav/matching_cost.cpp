#include "matching_cost.hpp"

#include "simd_lanes.hpp"

#include <algorithm>
#include <bit>

namespace marsokhod::nav::detail {
namespace {

constexpr int words_of(FeatureKind kind) {
  switch (kind) {
  case FeatureKind::census3x3:
    return 2;
  case FeatureKind::census5x5:
    return 5;
  case FeatureKind::rank5x5:
    return 3;
  }
  return 0;
}

// The words of the column whose features (rows y-1, y, y+1) are a, b, c.
template <FeatureKind Kind>
void pack_column(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint16_t* words) {
  if constexpr (Kind == FeatureKind::census3x3) {
    words[0] = static_cast<std::uint16_t>(a | (b << 8));
    words[1] = static_cast<std::uint16_t>(c);
  } else if constexpr (Kind == FeatureKind::census5x5) {
    words[0] = static_cast<std::uint16_t>(a);
    words[1] = static_cast<std::uint16_t>(b);
    words[2] = static_cast<std::uint16_t>(c);
    words[3] = static_cast<std::uint16_t>((a >> 16) | ((b >> 16) << 8));
    words[4] = static_cast<std::uint16_t>(c >> 16);
  } else {
    words[0] = static_cast<std::uint16_t>(a);
    words[1] = static_cast<std::uint16_t>(b);
    words[2] = static_cast<std::uint16_t>(c);
  }
}

// Columns of the band at y0, transposed: out[word][(i * kBandRows) + lane] is the column
// from + i (clamped to the image) of line `lane`, for i in start .. count - 1.
template <FeatureKind Kind>
void pack_band(const Image<std::uint32_t>& features, int y0, int from, int start, int count,
               std::array<std::pmr::vector<std::uint16_t>, 5>& out) {
  constexpr int kWords = words_of(Kind);
  const int last_row = features.height() - 1;
  const int last_column = features.width() - 1;
  // Rows y0 - 1 .. y0 + kBandRows, clamped.
  const std::uint32_t* rows[kBandRows + 2];
  for (int i = 0; i < kBandRows + 2; ++i)
    rows[i] = features.row(std::clamp(y0 - 1 + i, 0, last_row));
  std::uint16_t* targets[kWords];
  for (int word = 0; word < kWords; ++word)
    targets[word] = out[static_cast<std::size_t>(word)].data();
  std::uint16_t words[5];
  for (int i = start; i < count; ++i) {
    const int x = std::clamp(from + i, 0, last_column);
    for (int lane = 0; lane < kBandRows; ++lane) {
      pack_column<Kind>(rows[lane][x], rows[lane + 1][x], rows[lane + 2][x], words);
      for (int word = 0; word < kWords; ++word)
        targets[word][i * kBandRows + lane] = words[word];
    }
  }
}

// Census: Hamming distance summed over the words.
template <int Words>
struct BitDistance {
  static constexpr int words = Words;
  static Lanes16 apply(const Bits16* left, const std::uint16_t* const* right) {
    Bits16 bytes{};
    for (int word = 0; word < Words; ++word)
      bytes += byte_bit_counts(left[word] ^ load_lanes<Bits16>(right[word]));
    return std::bit_cast<Lanes16>(fold_bytes(bytes));
  }
};

// Rank: absolute difference summed over the words.
struct RankDistance {
  static constexpr int words = 3;
  static Lanes16 apply(const Bits16* left, const std::uint16_t* const* right) {
    Lanes16 sum{};
    for (int word = 0; word < words; ++word) {
      const Lanes16 difference =
          std::bit_cast<Lanes16>(left[word]) - load_lanes<Lanes16>(right[word]);
      sum += difference < 0 ? -difference : difference;
    }
    return sum;
  }
};

} // namespace

MatchingCost::MatchingCost(FeatureKind kind, int width, int max_disparity,
                           std::pmr::memory_resource* memory)
    : kind_(kind), width_(width), pad_(max_disparity + 2),
      right_columns_(width + pad_ + 1), left_{std::pmr::vector<std::uint16_t>(memory),
                                              std::pmr::vector<std::uint16_t>(memory),
                                              std::pmr::vector<std::uint16_t>(memory),
                                              std::pmr::vector<std::uint16_t>(memory),
                                              std::pmr::vector<std::uint16_t>(memory)},
      right_{std::pmr::vector<std::uint16_t>(memory), std::pmr::vector<std::uint16_t>(memory),
             std::pmr::vector<std::uint16_t>(memory), std::pmr::vector<std::uint16_t>(memory),
             std::pmr::vector<std::uint16_t>(memory)},
      column_cost_(static_cast<std::size_t>((kTileWidth + 2) * (max_disparity + 1) * kBandRows), 0,
                   memory) {
  for (std::size_t word = 0; word < static_cast<std::size_t>(words_of(kind)); ++word) {
    left_[word].resize(static_cast<std::size_t>((width + 2) * kBandRows));
    right_[word].resize(static_cast<std::size_t>(right_columns_ * kBandRows));
  }
}

void MatchingCost::load_band(const Image<std::uint32_t>& left, const Image<std::uint32_t>& right,
                             int y0, const BandLayout& layout) {
  // Only the right columns some window meets: left column x - 1 of a tile starting at x at the
  // window's largest disparity is the leftmost.
  int start = right_columns_;
  for (int x = 0; x < width_; x += kTileWidth)
    start = std::min(start, x - layout.first(x) - layout.cells(x) + pad_);
  start = std::max(start, 0);
  switch (kind_) {
  case FeatureKind::census3x3:
    pack_band<FeatureKind::census3x3>(left, y0, -1, 0, width_ + 2, left_);
    pack_band<FeatureKind::census3x3>(right, y0, -pad_, start, right_columns_, right_);
    break;
  case FeatureKind::census5x5:
    pack_band<FeatureKind::census5x5>(left, y0, -1, 0, width_ + 2, left_);
    pack_band<FeatureKind::census5x5>(right, y0, -pad_, start, right_columns_, right_);
    break;
  case FeatureKind::rank5x5:
    pack_band<FeatureKind::rank5x5>(left, y0, -1, 0, width_ + 2, left_);
    pack_band<FeatureKind::rank5x5>(right, y0, -pad_, start, right_columns_, right_);
    break;
  }
}

// One tile: the distances of columns first_pixel - 1 .. first_pixel + pixels over the tile's
// window, then each pixel's window sums.
template <class Distance>
void MatchingCost::tile_costs(const BandLayout& layout, int first_pixel, int pixels,
                              std::uint16_t* costs) {
  const int first = layout.first(first_pixel);
  const int cells = layout.cells(first_pixel);
  for (int i = 0; i < pixels + 2; ++i) {
    const int column = first_pixel - 1 + i;
    Bits16 left[kMaxWords];
    const std::uint16_t* right[kMaxWords];
    for (int word = 0; word < Distance::words; ++word) {
      left[word] = load_lanes<Bits16>(left_[static_cast<std::size_t>(word)].data() +
                                      (column + 1) * kBandRows);
      right[word] =
          right_[static_cast<std::size_t>(word)].data() + (column - first + pad_) * kBandRows;
    }
    std::uint16_t* out = column_cost_.data() + i * cells * kBandRows;
    for (int k = 0; k < cells; ++k) {
      store_lanes(out + k * kBandRows, Distance::apply(left, right));
      for (int word = 0; word < Distance::words; ++word)
        right[word] -= kBandRows; // the next disparity meets the column one to the left
    }
  }
  const Lanes16 padding = broadcast16(kPaddingCost);
  for (int p = 0; p < pixels; ++p) {
    const int x = first_pixel + p;
    const std::uint16_t* column = column_cost_.data() + p * cells * kBandRows;
    const int stride = cells * kBandRows;
    std::uint16_t* out = costs + layout.offset(x) * kBandRows;
    // Disparities up to x reach a right pixel; the rest are padding.
    const int reachable = std::clamp(x - first + 1, 0, cells);
    for (int k = 0; k < reachable; ++k) {
      const int at = k * kBandRows;
      store_lanes(out + at, load_lanes<Lanes16>(column + at) +
                                load_lanes<Lanes16>(column + stride + at) +
                                load_lanes<Lanes16>(column + 2 * stride + at));
    }
    for (int k = reachable; k < cells; ++k)
      store_lanes(out + k * kBandRows, padding);
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
    return compute_with<BitDistance<2>>(layout, costs);
  case FeatureKind::census5x5:
    return compute_with<BitDistance<5>>(layout, costs);
  case FeatureKind::rank5x5:
    return compute_with<RankDistance>(layout, costs);
  }
  return 0;
}

} // namespace marsokhod::nav::detail
