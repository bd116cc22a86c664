// The stereo matcher: options, result and match_stereo across the pyramid layers.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/features/brightness_features.hpp"
#include "marsokhod/nav/features/pair_pyramid.hpp"
#include "marsokhod/nav/matching/scanline_dp.hpp"
#include "marsokhod/nav/stereo/disparity_fill.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <memory_resource>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::nav {

/// How the stereo matcher searches (docs/navigation.md, "Stereo reconstruction").
struct StereoOptions {
  int max_disparity = 32; ///< largest disparity searched, pixels of the original images
  int min_disparity = 0;  ///< smallest disparity searched
  /// Layers of the image pyramid, the original included (1 = no pyramid); 0 chooses the number
  /// so that the top layer still spans a few disparities and enough pixels.
  int pyramid_levels = 0;
  /// Pixels searched beyond twice the coarser layer's disparities, on each side.
  int search_band = 0;
  /// Perspective prior for views of the ground: disparity generally decreases upwards, so at the
  /// top layer a row (matched from the bottom up) searches no further than the largest reliable
  /// disparity of the row below plus `prior_margin`. Off for scenes that are not ground views.
  bool ground_prior = true;
  int prior_margin = 2; ///< top-layer pixels of slack of the ground prior
  FeatureKind feature = FeatureKind::census3x3;
  DpPenalties penalties;
  /// Largest difference between the left and the right view's disparity of a reliable pixel.
  int lr_tolerance = 1;
  FillPolicy fill = FillPolicy::background_along_row;
  /// 3x3 median of every layer's filled disparity (not applied with FillPolicy::none).
  bool median = true;
  /// For each row of the left image, how many of its first columns show scene known to lie
  /// outside the right image (the navigation's level ground, docs/navigation.md); empty when
  /// nothing is known. Those pixels still get a disparity, but take no part in the right view:
  /// any match they have is wrong, and without this it may outbid the true match of one of
  /// the right image's first columns and fail the left-right check of the pixel that has it.
  /// The values stay owned by the caller.
  std::span<const std::int16_t> unseen_columns;
};

/// What one pyramid layer did.
struct StereoLayerStats {
  int level = 0; ///< 0 = original resolution
  int width = 0;
  int height = 0;
  std::uint64_t candidates = 0;   ///< match candidates evaluated
  std::uint64_t valid_pixels = 0; ///< pixels passing the left-right check
};

/// Dense disparity of the left image (x_right = x_left - d) with its reliability.
struct StereoResult {
  /// Sub-pixel disparity; +inf where unknown (unreliable pixels under FillPolicy::none, or
  /// everywhere when nothing could be matched).
  imaging::Image<float> disparity;
  /// 255 where the left-right check passed, 0 where the value was filled in or is unknown.
  imaging::Image<std::uint8_t> valid;
  std::uint64_t valid_pixels = 0;
  /// Coarsest layer first.
  std::pmr::vector<StereoLayerStats> layers;
  /// Why nothing could be matched (e.g. a uniform image); empty when matching ran.
  std::string reason;
};

/// Throws std::invalid_argument naming the first option out of range.
void validate(const StereoOptions& options);

/// The number of pyramid layers match_stereo uses for images of this size.
int pyramid_levels_for(int width, int height, const StereoOptions& options);

/// Matches a rectified grey stereo pair (same size, one channel) and returns the left image's
/// disparity. Every buffer, the result's included, comes from `memory`; the work done is
/// reported to `meter`. Throws std::invalid_argument for images of different sizes, images too
/// small for the pyramid or the search range, and bad options. A uniform (all black, all white)
/// image gives a result with no valid pixel and a reason. Instantiated for NullMeter,
/// CountingMeter and DynamicMeter.
template <class Meter = NullMeter>
StereoResult match_stereo(imaging::ImageView<const std::uint8_t> left,
                          imaging::ImageView<const std::uint8_t> right,
                          const StereoOptions& options, Meter& meter = null_meter,
                          std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
