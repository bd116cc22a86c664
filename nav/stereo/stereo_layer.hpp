// match_layer: one pyramid layer's input, output and matching (private to the stereo room).
#pragma once

// Matching of one pyramid layer (private to the stereo matcher).

#include "matching/band_layout.hpp"
#include "stereo/coarse_guide.hpp"

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/features/layer_features.hpp"
#include "marsokhod/nav/stereo/layered_matching.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <cstdint>
#include <memory_resource>
#include <span>

namespace marsokhod::nav::detail {

/// One layer's images, features and search limits.
struct LayerInput {
  imaging::ImageView<const std::uint8_t> left;
  const LayerFeatures* left_features = nullptr;
  const LayerFeatures* right_features = nullptr;
  DisparityLimits limits;
  /// The coarser layer's result, or null at the top layer (full search, ground prior).
  CoarseGuide* guide = nullptr;
  /// Whether to run the left-right check; without it every pixel counts as reliable. The
  /// coarse layers, whose disparities only seed the next layer's search, skip it, except the
  /// top layer under the ground prior, which needs reliable disparities to bound the rows above.
  bool check = true;
  /// Per row, how many first columns show scene the right image cannot show: left out of the
  /// right view (StereoOptions::unseen_columns; given at the original layer only); empty for
  /// none.
  std::span<const std::int16_t> unseen;
  /// Where the layer's rows go band by band as they are matched, or null to keep the whole
  /// layer in the output.
  const MatchedBandSink* bands = nullptr;
};

/// One layer's disparity (+inf where unreliable) and left-right validity: the whole layer, or
/// the band being matched when the layer goes out band by band.
struct LayerOutput {
  imaging::Image<float> disparity;
  imaging::Image<std::uint8_t> valid;
  int first_row = 0; ///< the layer row the images' row 0 holds
  std::uint64_t candidates = 0;
  std::uint64_t valid_pixels = 0;
};

/// Matches every scan line of the layer: ranges, costs, dynamic programme, choice, check.
template <class Meter>
LayerOutput match_layer(const LayerInput& input, const StereoOptions& options, Meter& meter,
                        std::pmr::memory_resource* memory);

} // namespace marsokhod::nav::detail
