// The Middlebury "bad pixels" score of a disparity estimate against ground truth.

#include "marsokhod/nav/stereo/disparity_metrics.hpp"

#include <cmath>
#include <stdexcept>

namespace marsokhod::nav {

BadPixelScore score_bad_pixels(imaging::ImageView<const float> estimate,
                               imaging::ImageView<const float> truth,
                               imaging::ImageView<const std::uint8_t> mask, float threshold) {
  if (estimate.width() != truth.width() || estimate.height() != truth.height())
    throw std::invalid_argument("score_bad_pixels: estimate and truth differ in size");
  const bool masked = !mask.empty();
  if (masked && (mask.width() != truth.width() || mask.height() != truth.height()))
    throw std::invalid_argument("score_bad_pixels: mask and truth differ in size");
  BadPixelScore score;
  for (int y = 0; y < truth.height(); ++y)
    for (int x = 0; x < truth.width(); ++x) {
      const float known = truth(x, y);
      if (!std::isfinite(known) || known <= 0.0F || (masked && mask(x, y) == 0))
        continue;
      ++score.scored;
      const float guess = estimate(x, y);
      if (!std::isfinite(guess) || std::fabs(guess - known) > threshold)
        ++score.bad;
    }
  return score;
}

} // namespace marsokhod::nav
