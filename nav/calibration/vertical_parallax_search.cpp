// Block matching in both directions for the vertical parallax calibration (private).

#include "calibration/vertical_parallax_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace marsokhod::nav::detail {
namespace {

constexpr double kNoMatch = -2.0; // below any correlation

/// Sums of one left block, kept to correlate it against many right blocks.
struct LeftBlock {
  int x0 = 0;
  int y0 = 0;
  std::int64_t sum = 0;
  double variance_n2 = 0.0; ///< n * sum(l^2) - sum(l)^2
};

class BlockMatcher {
public:
  BlockMatcher(imaging::ImageView<const std::uint8_t> left,
               imaging::ImageView<const std::uint8_t> right, const CalibrationOptions& options)
      : left_(left), right_(right), options_(options),
        pixels_(options.block_width * options.block_height) {}

  LeftBlock left_block(int x0, int y0) const {
    std::int64_t sum = 0;
    std::int64_t squares = 0;
    for (int y = y0; y < y0 + options_.block_height; ++y)
      for (int x = x0; x < x0 + options_.block_width; ++x) {
        const int value = left_(x, y);
        sum += value;
        squares += value * value;
      }
    return {x0, y0, sum, static_cast<double>(pixels_ * squares - sum * sum)};
  }

  double texture(const LeftBlock& block) const { return std::sqrt(block.variance_n2) / pixels_; }

  /// Zero-mean normalised cross-correlation with the right block whose top-left is (x0, y0).
  double correlation(const LeftBlock& block, int x0, int y0) const {
    std::int64_t sum = 0;
    std::int64_t squares = 0;
    std::int64_t products = 0;
    for (int row = 0; row < options_.block_height; ++row) {
      const std::uint8_t* l = left_.row(block.y0 + row) + block.x0;
      const std::uint8_t* r = right_.row(y0 + row) + x0;
      for (int col = 0; col < options_.block_width; ++col) {
        sum += r[col];
        squares += r[col] * r[col];
        products += l[col] * r[col];
      }
    }
    const double right_variance = static_cast<double>(pixels_ * squares - sum * sum);
    if (right_variance <= 0.0)
      return kNoMatch;
    const double covariance = static_cast<double>(pixels_ * products - block.sum * sum);
    return covariance / std::sqrt(block.variance_n2 * right_variance);
  }

private:
  imaging::ImageView<const std::uint8_t> left_;
  imaging::ImageView<const std::uint8_t> right_;
  const CalibrationOptions& options_;
  std::int64_t pixels_;
};

/// Offset of a parabola's vertex from the middle of three equally spaced samples.
double parabola_vertex(double before, double middle, double after) {
  const double curvature = before - 2.0 * middle + after;
  if (curvature >= 0.0)
    return 0.0; // not a peak: keep the integer position
  return 0.5 * (before - after) / curvature;
}

/// Correlations of one block over the whole (shift, disparity) search window.
class SearchWindow {
public:
  SearchWindow(int max_shift, int max_disparity)
      : max_shift_(max_shift), columns_(max_disparity + 1),
        values_(static_cast<std::size_t>((2 * max_shift + 1) * columns_), kNoMatch) {}

  double& at(int shift, int disparity) {
    return values_[static_cast<std::size_t>((shift + max_shift_) * columns_ + disparity)];
  }

private:
  int max_shift_;
  int columns_;
  std::vector<double> values_;
};

std::optional<ParallaxSample> match_block(const BlockMatcher& matcher, const LeftBlock& block,
                                          int centre_x, int centre_y, int half_height,
                                          const CalibrationOptions& options) {
  const int max_disparity = std::min(options.max_disparity, block.x0);
  SearchWindow window(options.max_shift, max_disparity);
  double best = kNoMatch;
  int best_shift = 0;
  int best_disparity = 0;
  for (int shift = -options.max_shift; shift <= options.max_shift; ++shift)
    for (int d = 0; d <= max_disparity; ++d) {
      const double c = matcher.correlation(block, block.x0 - d, centre_y + shift - half_height);
      window.at(shift, d) = c;
      if (c > best) {
        best = c;
        best_shift = shift;
        best_disparity = d;
      }
    }
  // A peak on the window's border may lie outside it: no sub-pixel position to trust.
  if (best < options.min_correlation || std::abs(best_shift) == options.max_shift ||
      best_disparity == 0 || best_disparity == max_disparity)
    return std::nullopt;
  ParallaxSample sample;
  sample.shift = best_shift + parabola_vertex(window.at(best_shift - 1, best_disparity), best,
                                              window.at(best_shift + 1, best_disparity));
  sample.disparity =
      best_disparity + parabola_vertex(window.at(best_shift, best_disparity - 1), best,
                                       window.at(best_shift, best_disparity + 1));
  sample.x = centre_x - sample.disparity;
  sample.y = centre_y;
  sample.correlation = best;
  return sample;
}

} // namespace

std::vector<ParallaxSample> match_parallax_blocks(imaging::ImageView<const std::uint8_t> left,
                                                  imaging::ImageView<const std::uint8_t> right,
                                                  const CalibrationOptions& options,
                                                  int& blocks_searched) {
  const BlockMatcher matcher(left, right, options);
  const int half_width = options.block_width / 2;
  const int half_height = options.block_height / 2;
  // Every vertical shift of the search must stay inside the image.
  const int first_row = half_height + options.max_shift;
  const int last_row = left.height() - 1 - half_height - options.max_shift;
  std::vector<ParallaxSample> samples;
  blocks_searched = 0;
  for (int y = first_row; y <= last_row; y += options.grid_step)
    for (int x = half_width + 1; x + half_width < left.width(); x += options.grid_step) {
      ++blocks_searched;
      const LeftBlock block = matcher.left_block(x - half_width, y - half_height);
      if (matcher.texture(block) < options.min_texture)
        continue;
      if (auto sample = match_block(matcher, block, x, y, half_height, options))
        samples.push_back(*sample);
    }
  return samples;
}

} // namespace marsokhod::nav::detail
