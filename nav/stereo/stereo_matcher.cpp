// The stereo matcher: a pyramid of layers matched coarse to fine, then filled.

#include "features/layer_features.hpp"
#include "matching/band_layout.hpp"
#include "stereo/coarse_guide.hpp"
#include "stereo/stereo_checks.hpp"
#include "stereo/stereo_layer.hpp"
#include "work/work_report.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/features/brightness_features.hpp"
#include "marsokhod/nav/features/image_pyramid.hpp"
#include "marsokhod/nav/stereo/disparity_fill.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>

namespace marsokhod::nav {
namespace {

// A grey level shared by every pixel, if the image is uniform.
std::optional<int> uniform_grey(imaging::ImageView<const std::uint8_t> image) {
  const std::uint8_t first = image(0, 0);
  for (int y = 0; y < image.height(); ++y) {
    const std::uint8_t* row = image.row(y);
    if (std::any_of(row, row + image.width(), [first](std::uint8_t v) { return v != first; }))
      return std::nullopt;
  }
  return first;
}

StereoResult unmatched(int width, int height, std::string reason,
                       std::pmr::memory_resource* memory) {
  StereoResult result{
      imaging::Image<float>(width, height, 1, std::numeric_limits<float>::infinity(), memory),
      imaging::Image<std::uint8_t>(width, height, 1, 0, memory), 0,
      std::pmr::vector<StereoLayerStats>(memory), std::move(reason)};
  return result;
}

std::optional<std::string> uniform_reason(imaging::ImageView<const std::uint8_t> left,
                                          imaging::ImageView<const std::uint8_t> right) {
  if (const auto grey = uniform_grey(left))
    return fmt::format("the left image is uniform (every pixel grey level {}): nothing to match",
                       *grey);
  if (const auto grey = uniform_grey(right))
    return fmt::format("the right image is uniform (every pixel grey level {}): nothing to match",
                       *grey);
  return std::nullopt;
}

// The pair's pyramid: the caller's images and the halved layers above them.
class Pyramid {
public:
  template <class Meter>
  Pyramid(imaging::ImageView<const std::uint8_t> left, imaging::ImageView<const std::uint8_t> right,
          int levels, Meter& meter, std::pmr::memory_resource* memory)
      : original_{left, right} {
    for (int level = 1; level < levels; ++level) {
      left_[static_cast<std::size_t>(level - 1)] =
          halve_image(layer(level - 1, imaging::Eye::left), meter, memory);
      right_[static_cast<std::size_t>(level - 1)] =
          halve_image(layer(level - 1, imaging::Eye::right), meter, memory);
    }
  }

  imaging::ImageView<const std::uint8_t> layer(int level, imaging::Eye eye) const {
    if (level == 0)
      return original_[eye == imaging::Eye::left ? 0 : 1];
    const auto& layers = eye == imaging::Eye::left ? left_ : right_;
    return layers[static_cast<std::size_t>(level - 1)].view();
  }

private:
  imaging::ImageView<const std::uint8_t> original_[2];
  // The pixels come from the caller's memory; only these handles live here.
  std::array<imaging::Image<std::uint8_t>, kMaxPyramidLevels> left_;
  std::array<imaging::Image<std::uint8_t>, kMaxPyramidLevels> right_;
};

detail::DisparityLimits layer_limits(const StereoOptions& options, int level, int width) {
  const int scale = 1 << level;
  const int low = options.min_disparity / scale;
  const int high = (options.max_disparity + scale - 1) / scale;
  return {low, std::max(low, std::min(high, width - 1))};
}

// Fill and smooth a layer: coarse layers are always filled since they guide the next layer.
template <class Meter>
void finish_layer(detail::LayerOutput& layer, FillPolicy fill, bool median, Meter& meter,
                  std::pmr::memory_resource* memory) {
  fill_disparity(layer.disparity.view(), layer.valid.view(), fill, meter, memory);
  if (!median || fill == FillPolicy::none)
    return;
  imaging::Image<float> smoothed(layer.disparity.width(), layer.disparity.height(), 1, 0.0F,
                                 memory);
  median3x3(layer.disparity.view(), smoothed.view(), meter, memory);
  layer.disparity = std::move(smoothed);
}

} // namespace

template <class Meter>
StereoResult match_stereo(imaging::ImageView<const std::uint8_t> left,
                          imaging::ImageView<const std::uint8_t> right,
                          const StereoOptions& options, Meter& meter,
                          std::pmr::memory_resource* memory) {
  detail::check_pair(left, right, options);
  if (auto reason = uniform_reason(left, right))
    return unmatched(left.width(), left.height(), std::move(*reason), memory);
  const int levels = pyramid_levels_for(left.width(), left.height(), options);
  const Pyramid pyramid(left, right, levels, meter, memory);
  std::pmr::vector<StereoLayerStats> stats(memory);
  std::optional<detail::LayerOutput> coarser;
  for (int level = levels - 1; level >= 0; --level) {
    const imaging::ImageView<const std::uint8_t> left_layer =
        pyramid.layer(level, imaging::Eye::left);
    const detail::LayerFeatures left_features =
        detail::layer_features(left_layer, options.feature, meter, memory);
    const detail::LayerFeatures right_features = detail::layer_features(
        pyramid.layer(level, imaging::Eye::right), options.feature, meter, memory);
    std::optional<detail::CoarseGuide> guide;
    if (coarser)
      guide.emplace(coarser->disparity.view(), memory);
    detail::report(meter, Work::search_range_pixel, guide ? guide->pixels() : 0);
    detail::LayerInput input{left_layer,
                             &left_features,
                             &right_features,
                             layer_limits(options, level, left_layer.width()),
                             guide ? &*guide : nullptr,
                             level == 0 || (options.ground_prior && !guide),
                             {}};
    // The original layer's check decides what is reliable. The top layer's check only bounds
    // the ground prior and, through the fill, guides the layers below; with the strip left out
    // there too, one site more lost its path and one path became unsafe (50 sites).
    if (level == 0)
      input.unseen = options.unseen_columns;
    detail::LayerOutput layer = detail::match_layer(input, options, meter, memory);
    stats.push_back(
        {level, left_layer.width(), left_layer.height(), layer.candidates, layer.valid_pixels});
    if (layer.valid_pixels == 0) {
      StereoResult result = unmatched(
          left.width(), left.height(),
          fmt::format("no pixel passed the left-right check at pyramid layer {}", level), memory);
      result.layers = std::move(stats);
      return result;
    }
    finish_layer(layer, level > 0 ? FillPolicy::background_along_row : options.fill, options.median,
                 meter, memory);
    coarser = std::move(layer);
  }
  StereoResult result{std::move(coarser->disparity),
                      std::move(coarser->valid),
                      coarser->valid_pixels,
                      std::move(stats),
                      {}};
  return result;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template StereoResult match_stereo<M>(imaging::ImageView<const std::uint8_t>,                    \
                                        imaging::ImageView<const std::uint8_t>,                    \
                                        const StereoOptions&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
