// Block matching for the vertical parallax calibration (private to the calibration room).
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/calibration/vertical_parallax_calibration.hpp"

#include <cstdint>
#include <vector>

namespace marsokhod::nav::detail {

/// Matches blocks of the left image on a grid against the right image, searching columns
/// (disparity) and rows (vertical shift) for the best zero-mean normalised cross-correlation.
/// Returns the matches that pass the texture, correlation and border tests, with the shift
/// refined to sub-pixel; counts every block centre considered in `blocks_searched`.
std::vector<ParallaxSample> match_parallax_blocks(imaging::ImageView<const std::uint8_t> left,
                                                  imaging::ImageView<const std::uint8_t> right,
                                                  const CalibrationOptions& options,
                                                  int& blocks_searched);

} // namespace marsokhod::nav::detail
