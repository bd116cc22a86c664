// Stereo options: their validation, the automatic pyramid depth and the input checks.

#include "stereo/stereo_checks.hpp"

#include "marsokhod/nav/stereo/stereo.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace marsokhod::nav {
namespace {

// No layer may be smaller than this: the 3x3 windows and the dynamic programme need a few
// pixels of context.
constexpr int kMinLayerSide = 8;
// The automatic choice stops adding layers before the top layer gets smaller than this or
// spans fewer disparities than kMinTopDisparities.
constexpr int kMinAutoTopSide = 24;
constexpr int kMinTopDisparities = 4;

// The message is only formatted when the condition fails, so that checking good options
// allocates nothing (the matcher takes all its memory from the caller).
template <class... Args>
void require(bool condition, fmt::format_string<Args...> message, Args&&... args) {
  if (!condition)
    throw std::invalid_argument("stereo options: " +
                                fmt::format(message, std::forward<Args>(args)...));
}

int ceil_shift(int value, int levels) {
  return (value + (1 << levels) - 1) >> levels;
}

} // namespace

void validate(const StereoOptions& options) {
  require(options.min_disparity >= 0, "min_disparity {} is negative", options.min_disparity);
  require(options.max_disparity >= options.min_disparity,
          "max_disparity {} is below min_disparity {}", options.max_disparity,
          options.min_disparity);
  require(options.pyramid_levels >= 0 && options.pyramid_levels <= kMaxPyramidLevels,
          "pyramid_levels {} is outside 0..{}", options.pyramid_levels, kMaxPyramidLevels);
  require(options.search_band >= 0 && options.search_band <= 64, "search_band {} is outside 0..64",
          options.search_band);
  require(options.prior_margin >= 0, "prior_margin {} is negative", options.prior_margin);
  require(options.lr_tolerance >= 0, "lr_tolerance {} is negative", options.lr_tolerance);
  const DpPenalties& p = options.penalties;
  const auto penalty_ok = [](int value) { return value >= 0 && value <= kMaxPenalty; };
  require(penalty_ok(p.small_step) && penalty_ok(p.large_step) && penalty_ok(p.large_step_at_edge),
          "penalties must lie within 0..{}", kMaxPenalty);
}

int pyramid_levels_for(int width, int height, const StereoOptions& options) {
  if (options.pyramid_levels > 0)
    return options.pyramid_levels;
  int levels = 1;
  while (levels < kMaxPyramidLevels && (width >> levels) >= kMinAutoTopSide &&
         (height >> levels) >= kMinAutoTopSide &&
         ceil_shift(options.max_disparity, levels) >= kMinTopDisparities)
    ++levels;
  return levels;
}

namespace detail {

// Throws std::invalid_argument when the pair cannot be matched with these options.
void check_pair(imaging::ImageView<const std::uint8_t> left,
                imaging::ImageView<const std::uint8_t> right, const StereoOptions& options) {
  validate(options);
  if (left.empty() || right.empty())
    throw std::invalid_argument("stereo: an image is empty");
  if (left.channels() != 1 || right.channels() != 1)
    throw std::invalid_argument("stereo: images must have one grey channel");
  if (left.width() != right.width() || left.height() != right.height())
    throw std::invalid_argument(
        fmt::format("stereo: the left image is {}x{} but the right is {}x{}", left.width(),
                    left.height(), right.width(), right.height()));
  check_pair_size(left.width(), left.height(), options);
}

void check_pair_size(int width, int height, const StereoOptions& options) {
  validate(options);
  if (width < 1 || height < 1)
    throw std::invalid_argument("stereo: an image is empty");
  if (options.max_disparity >= width)
    throw std::invalid_argument(
        fmt::format("stereo: max_disparity {} does not fit in an image {} pixels wide",
                    options.max_disparity, width));
  if (!options.unseen_columns.empty() &&
      options.unseen_columns.size() != static_cast<std::size_t>(height))
    throw std::invalid_argument(
        fmt::format("stereo: unseen_columns has {} rows but the images have {}",
                    options.unseen_columns.size(), height));
  const int levels = pyramid_levels_for(width, height, options);
  const int top_width = width >> (levels - 1);
  const int top_height = height >> (levels - 1);
  if (top_width < kMinLayerSide || top_height < kMinLayerSide)
    throw std::invalid_argument(fmt::format(
        "stereo: a {}x{} image is too small for {} pyramid layers: the top layer would be {}x{}, "
        "at least {}x{} is needed",
        width, height, levels, top_width, top_height, kMinLayerSide, kMinLayerSide));
}

} // namespace detail
} // namespace marsokhod::nav
