// A band's choices written back into the layer's rows (private to the stereo matcher).
#pragma once

// A band's choices written back into the layer's rows (private to the stereo matcher): the band
// holds its lines in lanes, column by column; the layer's images are row by row.

#include "matching/band_dp.hpp"
#include "stereo/stereo_layer.hpp"

#include <cstdint>
#include <memory_resource>
#include <vector>

namespace marsokhod::nav::detail {

/// The right view of a band line by line. Each line is led by entries of -1 (no disparity) for
/// the right pixels left of the image that a disparity up to max_disparity can point at, so
/// the check reads it without a bounds test.
class RightLines {
public:
  RightLines(int width, int max_disparity, std::pmr::memory_resource* memory);
  /// From the band's right view, [r * kBandRows + lane].
  void load(const std::int16_t* right);
  /// The largest disparity a left pixel may look back with.
  int max_disparity() const { return pad_ - 1; }
  /// Entries -max_disparity - 1 .. width - 1 exist.
  const std::int16_t* line(int lane) const {
    return data_.data() + static_cast<std::ptrdiff_t>(lane) * stride_ + pad_;
  }

private:
  int width_;
  int pad_;
  std::ptrdiff_t stride_;
  std::pmr::vector<std::int16_t> data_;
};

/// The left-right check of the first `rows` lines of the band at y0 against its right view: a
/// pixel that passes keeps its sub-pixel disparity and is valid, the others get +inf. Adds the
/// reliable pixels to output.valid_pixels and returns the largest whole disparity among them,
/// -1 if none. Throws std::range_error when a chosen disparity lies outside 0 .. the lines'
/// max_disparity: the choice's memory was struck, and occam's range check would stop there.
int check_band(const BandChoice& choice, const RightLines& right, int y0, int rows, int tolerance,
               LayerOutput& output);

/// Without the check: every pixel of the first `rows` lines keeps its choice and is valid.
void accept_band(const BandChoice& choice, int y0, int rows, LayerOutput& output);

} // namespace marsokhod::nav::detail
