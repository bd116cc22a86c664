// LayeredMatching: the stereo matcher's walk down the pyramid, one layer at a time.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/features/layer_features.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <functional>
#include <memory_resource>
#include <optional>
#include <string>

namespace marsokhod::nav {

/// Why a pair cannot be matched at all (an image of one grey level), or nothing.
std::optional<std::string> uniform_pair_reason(imaging::ImageView<const std::uint8_t> left,
                                               imaging::ImageView<const std::uint8_t> right);

/// The result of a pair that could not be matched: every pixel unknown, none valid.
StereoResult unmatched_stereo(int width, int height, std::string reason,
                              std::pmr::memory_resource* memory);

/// Rows per band of the matcher: the scan lines its dynamic programme runs side by side.
inline constexpr int kMatchedBandRows = 8;

/// A band of the original layer's rows as matched and checked, before the fill and the median:
/// rows first_row .. first_row + disparity.height() - 1, the disparity +inf where unreliable.
struct MatchedBand {
  int first_row = 0;
  imaging::ImageView<const float> disparity;
  imaging::ImageView<const std::uint8_t> valid;
};

/// Takes the original layer's bands as they are matched (the view is reused for the next band).
using MatchedBandSink = std::function<void(const MatchedBand&)>;

/// What is left of the original layer once all its bands are in: the pixels the check rejected
/// filled (options.fill) and the 3x3 median (options.median, when something was filled in).
/// LayeredMatching does it itself unless it hands the layer on band by band. Instantiated for
/// NullMeter, CountingMeter and DynamicMeter.
template <class Meter>
void finish_original_layer(imaging::Image<float>& disparity,
                           imaging::ImageView<const std::uint8_t> valid,
                           const StereoOptions& options, Meter& meter,
                           std::pmr::memory_resource* memory);

/// match_stereo's walk down the pyramid, given one layer at a time, coarsest first, with the
/// layer's features made elsewhere: match_stereo drives it with the features it makes itself,
/// the occam program with the features its features process sends. Each layer is matched,
/// checked, filled and smoothed, and guides the next; the coarser layer's buffers are given
/// back as soon as the finer one is done.
class LayeredMatching {
public:
  /// The pair's size and the options are checked as match_stereo checks them
  /// (std::invalid_argument). Every buffer comes from `memory`. With `bands` (which must
  /// outlive the walk), the original layer is not kept: each of its bands goes to `bands` as
  /// soon as it is matched, and finish_original_layer() is left to whoever assembles them (the
  /// coarser layers, which guide the next, are kept whole either way).
  LayeredMatching(int width, int height, const StereoOptions& options,
                  std::pmr::memory_resource* memory, const MatchedBandSink* bands = nullptr);

  int levels() const { return levels_; }
  /// The layer the next match_layer() call must be given; -1 once finished.
  int next_level() const { return next_level_; }
  bool finished() const { return next_level_ < 0; }

  /// Matches layer next_level(): `left` is that layer's left image, `left_features` and
  /// `right_features` its features. A layer in which no pixel passes the left-right check
  /// ends the walk with an unmatched result. Instantiated for NullMeter, CountingMeter and
  /// DynamicMeter.
  template <class Meter>
  void match_layer(imaging::ImageView<const std::uint8_t> left, const LayerFeatures& left_features,
                   const LayerFeatures& right_features, Meter& meter);

  /// The finished walk's result (std::logic_error before the walk is finished). When the
  /// original layer went out band by band, the disparity and validity are empty, also for a
  /// failed walk: the rest (valid pixels, layers, the reason) is what the assembler needs.
  StereoResult take_result();

private:
  int width_;
  int height_;
  StereoOptions options_;
  std::pmr::memory_resource* memory_;
  const MatchedBandSink* bands_;
  int levels_;
  int next_level_;
  std::pmr::vector<StereoLayerStats> stats_;
  imaging::Image<float> disparity_; ///< the last layer's, filled: the next layer's guide
  imaging::Image<std::uint8_t> valid_;
  std::uint64_t valid_pixels_ = 0;
  std::optional<StereoResult> failed_;
};

} // namespace marsokhod::nav
