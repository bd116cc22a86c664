// Transposing a band's feature columns for the matching cost kernels (private).

#include "matching/band_columns.hpp"

#include <algorithm>
#include <cstring>

namespace marsokhod::nav::detail {
namespace {

using Bytes16 = std::uint8_t __attribute__((vector_size(16)));
using Words8 = std::uint16_t __attribute__((vector_size(16)));
using Dwords4 = std::uint32_t __attribute__((vector_size(16)));
using Qwords2 = std::uint64_t __attribute__((vector_size(16)));

// Rows a band's windows meet: y0 - 1 .. y0 + kBandRows.
constexpr int kBandSpan = kBandRows + 2;
constexpr int kBlock = 16; // columns transposed at once

// Interleaves the low (high) halves of a and b in units of T.
template <class T>
Bytes16 low_units(Bytes16 a, Bytes16 b) {
  const auto x = std::bit_cast<T>(a);
  const auto y = std::bit_cast<T>(b);
  if constexpr (sizeof(x[0]) == 1)
    return std::bit_cast<Bytes16>(
        __builtin_shufflevector(x, y, 0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23));
  else if constexpr (sizeof(x[0]) == 2)
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 0, 8, 1, 9, 2, 10, 3, 11));
  else if constexpr (sizeof(x[0]) == 4)
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 0, 4, 1, 5));
  else
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 0, 2));
}
template <class T>
Bytes16 high_units(Bytes16 a, Bytes16 b) {
  const auto x = std::bit_cast<T>(a);
  const auto y = std::bit_cast<T>(b);
  if constexpr (sizeof(x[0]) == 1)
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 8, 24, 9, 25, 10, 26, 11, 27, 12,
                                                          28, 13, 29, 14, 30, 15, 31));
  else if constexpr (sizeof(x[0]) == 2)
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 4, 12, 5, 13, 6, 14, 7, 15));
  else if constexpr (sizeof(x[0]) == 4)
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 2, 6, 3, 7));
  else
    return std::bit_cast<Bytes16>(__builtin_shufflevector(x, y, 1, 3));
}

// One round of a 16 x 16 byte transpose: pairs vectors i and i + half within groups of
// 2 * half, interleaving units of T.
template <class T>
void interleave_round(Bytes16 (&v)[kBlock], int half) {
  Bytes16 out[kBlock];
  for (int group = 0; group < kBlock; group += 2 * half)
    for (int i = 0; i < half; ++i) {
      out[group + 2 * i] = low_units<T>(v[group + i], v[group + i + half]);
      out[group + 2 * i + 1] = high_units<T>(v[group + i], v[group + i + half]);
    }
  std::copy(out, out + kBlock, v);
}

// Columns x .. x + 15 of the band's rows as 16 columns of 16 bytes (bytes 10..15 zero).
void transpose_block(const std::uint8_t* const* rows, int x, std::uint8_t* out) {
  Bytes16 v[kBlock] = {};
  for (int i = 0; i < kBandSpan; ++i)
    std::memcpy(&v[i], rows[i] + x, sizeof v[i]);
  interleave_round<Bytes16>(v, 1);
  interleave_round<Words8>(v, 2);
  interleave_round<Dwords4>(v, 4);
  interleave_round<Qwords2>(v, 8);
  std::memcpy(out, v, sizeof v);
}

// census3x3: column i is image column first + i, clamped.
void load_bytes(const imaging::Image<std::uint8_t>& features, int y0, int first, int start,
                int count, std::uint16_t* data) {
  const int width = features.width();
  const std::uint8_t* rows[kBandSpan];
  for (int i = 0; i < kBandSpan; ++i)
    rows[i] = features.row(std::clamp(y0 - 1 + i, 0, features.height() - 1));
  auto* out = reinterpret_cast<std::uint8_t*>(data);
  int i = start;
  while (i < count) {
    const int x = first + i;
    if (x >= 0 && x + kBlock <= width && i + kBlock <= count) {
      transpose_block(rows, x, out + static_cast<std::ptrdiff_t>(i) * kBlock);
      i += kBlock;
      continue;
    }
    const int column = std::clamp(x, 0, width - 1);
    std::uint8_t* slot = out + static_cast<std::ptrdiff_t>(i) * kBlock;
    for (int row = 0; row < kBandSpan; ++row)
      slot[row] = rows[row][column];
    std::fill(slot + kBandSpan, slot + kBlock, std::uint8_t{0});
    ++i;
  }
}

// The words of the column whose features (rows y-1, y, y+1) are a, b, c.
void pack_words(FeatureKind kind, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                std::uint16_t* words) {
  words[0] = static_cast<std::uint16_t>(a);
  words[kBandRows] = static_cast<std::uint16_t>(b);
  words[2 * kBandRows] = static_cast<std::uint16_t>(c);
  if (kind != FeatureKind::census5x5)
    return;
  words[3 * kBandRows] = static_cast<std::uint16_t>((a >> 16) | ((b >> 16) << 8));
  words[4 * kBandRows] = static_cast<std::uint16_t>(c >> 16);
}

// census5x5 and rank5x5.
void load_words(FeatureKind kind, const imaging::Image<std::uint32_t>& features, int y0, int first,
                int start, int count, int stride, std::uint16_t* data) {
  const std::uint32_t* rows[kBandSpan];
  for (int i = 0; i < kBandSpan; ++i)
    rows[i] = features.row(std::clamp(y0 - 1 + i, 0, features.height() - 1));
  for (int i = start; i < count; ++i) {
    const int x = std::clamp(first + i, 0, features.width() - 1);
    std::uint16_t* column = data + static_cast<std::ptrdiff_t>(i) * stride;
    for (int lane = 0; lane < kBandRows; ++lane)
      pack_words(kind, rows[lane][x], rows[lane + 1][x], rows[lane + 2][x], column + lane);
  }
}

} // namespace

BandColumns::BandColumns(FeatureKind kind, int first, int count, std::pmr::memory_resource* memory)
    : kind_(kind), first_(first), count_(count), stride_(column_stride(kind)),
      data_(static_cast<std::size_t>(count) * static_cast<std::size_t>(stride_), 0, memory) {}

void BandColumns::load(const LayerFeatures& features, int y0, int start) {
  if (kind_ == FeatureKind::census3x3)
    load_bytes(features.bytes, y0, first_, start, count_, data_.data());
  else
    load_words(kind_, features.words, y0, first_, start, count_, stride_, data_.data());
}

} // namespace marsokhod::nav::detail
