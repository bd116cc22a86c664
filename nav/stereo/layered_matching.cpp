// The stereo matcher's walk down the pyramid: each layer matched, checked, filled, smoothed.

#include "marsokhod/nav/stereo/layered_matching.hpp"

#include "matching/band_layout.hpp"
#include "stereo/coarse_guide.hpp"
#include "stereo/stereo_checks.hpp"
#include "stereo/stereo_layer.hpp"
#include "work/work_report.hpp"

#include "marsokhod/nav/stereo/disparity_fill.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

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

detail::DisparityLimits layer_limits(const StereoOptions& options, int level, int width) {
  const int scale = 1 << level;
  const int low = options.min_disparity / scale;
  const int high = (options.max_disparity + scale - 1) / scale;
  return {low, std::max(low, std::min(high, width - 1))};
}

// Fill and smooth a layer: coarse layers are always filled since they guide the next layer.
template <class Meter>
void finish_layer(imaging::Image<float>& disparity, imaging::ImageView<const std::uint8_t> valid,
                  FillPolicy fill, bool median, Meter& meter, std::pmr::memory_resource* memory) {
  fill_disparity(disparity.view(), valid, fill, meter, memory);
  if (!median || fill == FillPolicy::none)
    return;
  imaging::Image<float> smoothed(disparity.width(), disparity.height(), 1, 0.0F, memory);
  median3x3(disparity.view(), smoothed.view(), meter, memory);
  disparity = std::move(smoothed);
}

} // namespace

std::optional<std::string> uniform_pair_reason(imaging::ImageView<const std::uint8_t> left,
                                               imaging::ImageView<const std::uint8_t> right) {
  if (const auto grey = uniform_grey(left))
    return fmt::format("the left image is uniform (every pixel grey level {}): nothing to match",
                       *grey);
  if (const auto grey = uniform_grey(right))
    return fmt::format("the right image is uniform (every pixel grey level {}): nothing to match",
                       *grey);
  return std::nullopt;
}

template <class Meter>
void finish_original_layer(imaging::Image<float>& disparity,
                           imaging::ImageView<const std::uint8_t> valid,
                           const StereoOptions& options, Meter& meter,
                           std::pmr::memory_resource* memory) {
  finish_layer(disparity, valid, options.fill, options.median, meter, memory);
}

StereoResult unmatched_stereo(int width, int height, std::string reason,
                              std::pmr::memory_resource* memory) {
  StereoResult result{
      imaging::Image<float>(width, height, 1, std::numeric_limits<float>::infinity(), memory),
      imaging::Image<std::uint8_t>(width, height, 1, 0, memory), 0,
      std::pmr::vector<StereoLayerStats>(memory), std::move(reason)};
  return result;
}

LayeredMatching::LayeredMatching(int width, int height, const StereoOptions& options,
                                 std::pmr::memory_resource* memory, const MatchedBandSink* bands)
    : width_(width), height_(height), options_(options), memory_(memory), bands_(bands),
      levels_((detail::check_pair_size(width, height, options),
               pyramid_levels_for(width, height, options))),
      next_level_(levels_ - 1), stats_(memory), disparity_(memory), valid_(memory) {}

template <class Meter>
void LayeredMatching::match_layer(imaging::ImageView<const std::uint8_t> left,
                                  const LayerFeatures& left_features,
                                  const LayerFeatures& right_features, Meter& meter) {
  if (finished())
    throw std::logic_error("LayeredMatching: every layer is already matched");
  const int level = next_level_;
  std::optional<detail::CoarseGuide> guide;
  if (!disparity_.empty())
    guide.emplace(disparity_.view(), memory_);
  detail::report(meter, Work::search_range_pixel, guide ? guide->pixels() : 0);
  detail::LayerInput input{left,
                           &left_features,
                           &right_features,
                           layer_limits(options_, level, left.width()),
                           guide ? &*guide : nullptr,
                           level == 0 || (options_.ground_prior && !guide),
                           {}};
  // The original layer's check decides what is reliable. The top layer's check only bounds
  // the ground prior and, through the fill, guides the layers below; with the strip left out
  // there too, one site more lost its path and one path became unsafe (50 sites).
  if (level == 0) {
    input.unseen = options_.unseen_columns;
    input.bands = bands_;
  }
  detail::LayerOutput layer = detail::match_layer(input, options_, meter, memory_);
  stats_.push_back({level, left.width(), left.height(), layer.candidates, layer.valid_pixels});
  if (layer.valid_pixels == 0) {
    std::string reason =
        fmt::format("no pixel passed the left-right check at pyramid layer {}", level);
    failed_ = bands_ != nullptr ? unmatched_stereo(0, 0, std::move(reason), memory_)
                                : unmatched_stereo(width_, height_, std::move(reason), memory_);
    failed_->layers = std::move(stats_);
    next_level_ = -1;
    return;
  }
  if (input.bands == nullptr) {
    if (level > 0)
      finish_layer(layer.disparity, layer.valid, FillPolicy::background_along_row, options_.median,
                   meter, memory_);
    else
      finish_original_layer(layer.disparity, layer.valid, options_, meter, memory_);
  }
  guide.reset();
  // Handed on band by band, the original layer leaves nothing behind but its figures.
  disparity_ = input.bands != nullptr ? imaging::Image<float>(memory_) : std::move(layer.disparity);
  valid_ = input.bands != nullptr ? imaging::Image<std::uint8_t>(memory_) : std::move(layer.valid);
  valid_pixels_ = layer.valid_pixels;
  --next_level_;
}

StereoResult LayeredMatching::take_result() {
  if (!finished())
    throw std::logic_error("LayeredMatching: the walk is not finished");
  if (failed_)
    return std::move(*failed_);
  StereoResult result{
      std::move(disparity_), std::move(valid_), valid_pixels_, std::move(stats_), {}};
  return result;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template void LayeredMatching::match_layer<M>(imaging::ImageView<const std::uint8_t>,            \
                                                const LayerFeatures&, const LayerFeatures&, M&);   \
  template void finish_original_layer<M>(imaging::Image<float>&,                                   \
                                         imaging::ImageView<const std::uint8_t>,                   \
                                         const StereoOptions&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
