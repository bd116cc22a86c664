// Vertical parallax calibration: block matches fitted by a robust least-squares quadratic.

#include "marsokhod/nav/calibration/vertical_parallax_calibration.hpp"

#include "calibration/vertical_parallax_search.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace marsokhod::nav {
namespace {

constexpr int kTerms = 6;
constexpr int kMinSamples = 12;
constexpr int kMaxRejectionRounds = 8;
constexpr double kMinThreshold = 0.25; // rows: sub-pixel matches scatter by about 0.1
/// Passes of match and fit: every pass after the first measures what is left after removing
/// the map so far, near zero shift, where the parabola's pull towards whole rows vanishes.
constexpr int kPasses = 3;

/// The quadratic's terms at a sample, in coordinates scaled by `scale` so that the normal
/// equations stay well conditioned.
Eigen::Matrix<double, 1, kTerms> terms(double u, double v) {
  Eigen::Matrix<double, 1, kTerms> row;
  row << 1.0, u, v, u * u, u * v, v * v;
  return row;
}

double median_of(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

struct Fit {
  VerticalParallaxMap map;
  double rms = 0.0;
};

Fit least_squares(const std::vector<ParallaxSample>& samples, int width, int height) {
  const double cx = 0.5 * (width - 1);
  const double cy = 0.5 * (height - 1);
  const double scale = 0.5 * std::max(width, height);
  std::vector<const ParallaxSample*> used;
  for (const ParallaxSample& s : samples)
    if (s.inlier)
      used.push_back(&s);
  if (static_cast<int>(used.size()) < kMinSamples)
    throw CalibrationError(fmt::format("only {} block matches agree on a vertical parallax, at "
                                       "least {} are needed: the pair has too little texture",
                                       used.size(), kMinSamples));
  Eigen::MatrixXd a(static_cast<Eigen::Index>(used.size()), kTerms);
  Eigen::VectorXd b(static_cast<Eigen::Index>(used.size()));
  for (std::size_t i = 0; i < used.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    a.row(row) = terms((used[i]->x - cx) / scale, (used[i]->y - cy) / scale);
    b(row) = used[i]->shift;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < kTerms)
    throw CalibrationError("the matched blocks do not spread over the image enough to fit a "
                           "vertical parallax map");
  const Eigen::VectorXd c = qr.solve(b);
  Fit fit;
  fit.map.width = width;
  fit.map.height = height;
  const double s2 = scale * scale;
  fit.map.coefficients = {c(0), c(1) / scale, c(2) / scale, c(3) / s2, c(4) / s2, c(5) / s2};
  fit.rms = std::sqrt((a * c - b).squaredNorm() / static_cast<double>(used.size()));
  return fit;
}

void validate(const CalibrationOptions& o) {
  auto require = [](bool ok, const char* what) {
    if (!ok)
      throw CalibrationError(fmt::format("calibration option out of range: {}", what));
  };
  require(o.max_disparity >= 2, "max_disparity must be at least 2");
  require(o.max_shift >= 2, "max_shift must be at least 2");
  require(o.block_width >= 3 && o.block_width % 2 == 1, "block_width must be odd and >= 3");
  require(o.block_height >= 3 && o.block_height % 2 == 1, "block_height must be odd and >= 3");
  require(o.grid_step >= 1, "grid_step must be at least 1");
  require(o.min_correlation > -1.0 && o.min_correlation <= 1.0,
          "min_correlation must lie in (-1, 1]");
  require(o.min_texture >= 0.0, "min_texture must not be negative");
}

void check_images(imaging::ImageView<const std::uint8_t> left,
                  imaging::ImageView<const std::uint8_t> right, const CalibrationOptions& o) {
  if (left.channels() != 1 || right.channels() != 1)
    throw CalibrationError("calibration needs grey images");
  if (left.width() != right.width() || left.height() != right.height())
    throw CalibrationError(fmt::format("the calibration pair differs in size: {}x{} and {}x{}",
                                       left.width(), left.height(), right.width(), right.height()));
  const int rows_needed = std::max(kMinCalibrationSide, o.block_height + 2 * o.max_shift + 1);
  const int columns_needed = std::max(kMinCalibrationSide, o.block_width + 3);
  if (left.width() < columns_needed || left.height() < rows_needed)
    throw CalibrationError(fmt::format("{}x{} images are too small to calibrate: a block and its "
                                       "vertical search need {}x{} pixels",
                                       left.width(), left.height(), columns_needed, rows_needed));
}

} // namespace

VerticalParallaxMap fit_vertical_parallax(std::vector<ParallaxSample>& samples, int width,
                                          int height, double* rms_residual) {
  for (ParallaxSample& s : samples)
    s.inlier = true;
  Fit fit = least_squares(samples, width, height);
  for (int round = 0; round < kMaxRejectionRounds; ++round) {
    std::vector<double> deviations;
    for (const ParallaxSample& s : samples)
      if (s.inlier)
        deviations.push_back(std::fabs(s.shift - fit.map.shift_at(s.x, s.y)));
    const double threshold = std::max(kMinThreshold, 3.0 * 1.4826 * median_of(deviations));
    bool changed = false;
    for (ParallaxSample& s : samples) {
      const bool inlier = std::fabs(s.shift - fit.map.shift_at(s.x, s.y)) <= threshold;
      changed = changed || inlier != s.inlier;
      s.inlier = inlier;
    }
    if (!changed)
      break;
    fit = least_squares(samples, width, height);
  }
  if (rms_residual != nullptr)
    *rms_residual = fit.rms;
  return fit.map;
}

CalibrationResult calibrate_vertical_parallax(imaging::ImageView<const std::uint8_t> left,
                                              imaging::ImageView<const std::uint8_t> right,
                                              const CalibrationOptions& options) {
  validate(options);
  check_images(left, right, options);
  CalibrationResult result;
  result.map.width = left.width();
  result.map.height = left.height();
  imaging::Image<std::uint8_t> aligned = imaging::to_image(right);
  for (int pass = 0; pass < kPasses; ++pass) {
    std::vector<ParallaxSample> samples =
        detail::match_parallax_blocks(left, aligned, options, result.blocks_searched);
    const VerticalParallaxMap residual =
        fit_vertical_parallax(samples, left.width(), left.height(), &result.rms_residual);
    for (int i = 0; i < kTerms; ++i)
      result.map.coefficients[static_cast<std::size_t>(i)] +=
          residual.coefficients[static_cast<std::size_t>(i)];
    result.inliers = static_cast<int>(
        std::count_if(samples.begin(), samples.end(), [](const auto& s) { return s.inlier; }));
    if (pass == 0)
      result.samples = std::move(samples);
    if (pass + 1 < kPasses)
      aligned = remove_vertical_parallax(right, result.map);
  }
  // A quadratic fitted to matches in one part of the image can run away beyond them.
  const std::string problem = calibration_map_problem(result.map);
  if (!problem.empty())
    throw CalibrationError(fmt::format("the fitted map cannot be used: {} ({} blocks matched of "
                                       "{}; they do not cover the image well enough)",
                                       problem, result.samples.size(), result.blocks_searched));
  return result;
}

} // namespace marsokhod::nav
