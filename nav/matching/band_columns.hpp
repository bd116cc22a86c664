// A band's feature columns, transposed for the cost kernels (private to the stereo matcher).
#pragma once

// The feature columns of a band of scan lines, transposed for the cost kernels (private to the
// stereo matcher).

#include "matching/band_layout.hpp"

#include "marsokhod/nav/features/layer_features.hpp"

#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav::detail {

/// Column x of the band whose first row is y0 describes, for each line y0 + lane, the features
/// of rows y0 + lane - 1 .. y0 + lane + 1 at x (rows and columns clamped to the layer): what
/// one column of that line's 3x3 windows compares.
///
/// census3x3 stores a column as 16 bytes, byte i the feature of row y0 - 1 + i (i < 10): one
/// vector holds the ten rows the band's eight windows meet. The wider kinds store words by
/// lane: census5x5 five (the low 16 bits of each row, then the high 8 bits of the first two
/// rows and of the third), rank5x5 three (one rank a row).
/// 16-bit words of one column: census3x3 8 (16 bytes), census5x5 5 x kBandRows, rank5x5
/// 3 x kBandRows.
constexpr int column_stride(FeatureKind kind) {
  switch (kind) {
  case FeatureKind::census3x3:
    return 8;
  case FeatureKind::census5x5:
    return 5 * kBandRows;
  case FeatureKind::rank5x5:
    return 3 * kBandRows;
  }
  return 0;
}

class BandColumns {
public:
  /// Columns first .. first + count - 1.
  BandColumns(FeatureKind kind, int first, int count, std::pmr::memory_resource* memory);

  /// Loads the columns from first + start on for the band whose first row is y0.
  void load(const LayerFeatures& features, int y0, int start);

  /// 16-bit words from one column to the next.
  int stride() const { return stride_; }
  const std::uint16_t* column(int x) const {
    return data_.data() + static_cast<std::ptrdiff_t>(x - first_) * stride_;
  }

private:
  FeatureKind kind_;
  int first_;
  int count_;
  int stride_;
  std::pmr::vector<std::uint16_t> data_;
};

} // namespace marsokhod::nav::detail
