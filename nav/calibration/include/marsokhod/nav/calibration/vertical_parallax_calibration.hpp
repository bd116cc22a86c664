// Vertical parallax calibration: the parallax map fitted to block matches of one stereo pair.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"

#include <cstdint>
#include <vector>

namespace marsokhod::nav {

/// How a calibration pair is searched (docs/navigation.md, "Vertical parallax calibration").
struct CalibrationOptions {
  int max_disparity = 64; ///< horizontal search 0..max_disparity, pixels
  int max_shift = 8;      ///< vertical search -max_shift..max_shift, rows
  int block_width = 15;   ///< matched blocks are wide and low: the ground's disparity changes
  int block_height = 7;   ///< from row to row, so a tall block would be sheared
  int grid_step = 4;      ///< distance between block centres, pixels
  /// Smallest zero-mean normalised cross-correlation of an accepted match.
  double min_correlation = 0.85;
  /// Smallest grey-level standard deviation of an accepted left block (texture).
  double min_texture = 3.0;
};

/// One block matched in both directions.
struct ParallaxSample {
  double x = 0.0;     ///< block centre column in the right image, after the shift is removed
  double y = 0.0;     ///< block centre row (that of the left block)
  double shift = 0.0; ///< rows, sub-pixel
  double disparity = 0.0;
  double correlation = 0.0;
  bool inlier = false; ///< kept by the robust fit
};

/// The fitted map and how it was obtained.
struct CalibrationResult {
  VerticalParallaxMap map;
  /// Every accepted block match of the raw pair, inliers of the first fit marked.
  std::vector<ParallaxSample> samples;
  int blocks_searched = 0;
  /// Inliers of the last pass, which matches the pair with the map so far removed.
  int inliers = 0;
  double rms_residual = 0.0; ///< of the last pass's inliers about its fit, rows
};

/// Estimates the vertical parallax map of a pair (same size, grey): blocks on a grid are
/// searched both horizontally and vertically for the best zero-mean normalised correlation
/// (robust to gain and offset between the cameras), refined to sub-pixel by a parabola
/// through the correlation around the best row, and a quadratic is fitted to the shifts by
/// least squares with outliers rejected. Two more passes match the pair with the map so far
/// removed and add the fitted remainder: near zero shift the parabola's pull towards whole
/// rows vanishes. Throws CalibrationError when the images differ in
/// size, are too small for one block and its search, or give too few good matches (uniform
/// images, no texture) for the fit.
CalibrationResult calibrate_vertical_parallax(imaging::ImageView<const std::uint8_t> left,
                                              imaging::ImageView<const std::uint8_t> right,
                                              const CalibrationOptions& options = {});

/// The least-squares quadratic through the inlier samples after iterative rejection of
/// samples further than max(0.25 row, 3 robust sigmas) from the fit; marks the inliers.
/// Throws CalibrationError with fewer than 12 samples left.
VerticalParallaxMap fit_vertical_parallax(std::vector<ParallaxSample>& samples, int width,
                                          int height, double* rms_residual = nullptr);

} // namespace marsokhod::nav
