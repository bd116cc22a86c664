// Scoring disparity maps: the Middlebury "bad" metric against ground truth.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <cstdint>

namespace marsokhod::nav {

/// How many scored pixels an estimate got wrong.
struct BadPixelScore {
  std::uint64_t scored = 0; ///< pixels with known ground truth (inside the mask, if any)
  std::uint64_t bad = 0;    ///< of those, missing estimates and errors above the threshold
  double percent() const {
    return scored == 0 ? 0.0 : 100.0 * static_cast<double>(bad) / static_cast<double>(scored);
  }
};

/// The Middlebury "bad" metric: among the pixels whose ground truth is known (finite and
/// above zero) and, when `mask` is not empty, whose mask value is non-zero, the share whose
/// estimate is missing (non-finite) or differs from the truth by more than `threshold`.
BadPixelScore score_bad_pixels(imaging::ImageView<const float> estimate,
                               imaging::ImageView<const float> truth,
                               imaging::ImageView<const std::uint8_t> mask, float threshold);

} // namespace marsokhod::nav
