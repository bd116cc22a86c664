// Matching every pair of a PAIRS.tsv index and scoring it against its ground truth (bad-1.0).
#pragma once

#include "marsokhod/nav/stereo/stereo.hpp"

#include <optional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// What `marsokhod eval stereo` was asked to do.
struct StereoEvaluationOptions {
  std::string index;   ///< PAIRS.tsv
  std::string out_dir; ///< where to write each pair's disparity, empty for nowhere
  /// Search range of pairs whose index gives no largest ground-truth disparity.
  int fallback_max_disparity = 64;
  /// Grey-level distortion of every right image before matching (gain, then offset), to test
  /// robustness to cameras with different responses; 1 and 0 leave the images untouched.
  double right_gain = 1.0;
  double right_offset = 0.0;
  nav::StereoOptions stereo;
};

/// One pair's figures; the bad percentages are absent without ground truth.
struct PairEvaluation {
  std::string name;
  int width = 0;
  int height = 0;
  int max_disparity = 0;
  std::optional<double> bad_percent;        ///< bad-1.0 over every pixel with ground truth
  std::optional<double> bad_percent_nonocc; ///< the same over the non-occluded mask
  double valid_percent = 0.0;               ///< pixels passing the left-right check
  double seconds = 0.0;                     ///< matching only, host wall clock
  std::string note;
};

/// Matches and scores every pair of the index; throws EvaluationError on bad input (naming the
/// index file and line, or the image file).
std::vector<PairEvaluation> evaluate_stereo_pairs(const StereoEvaluationOptions& options);

/// Mean bad-1.0 percentage over the pairs that have ground truth (absent if none has).
std::optional<double> mean_bad_percent(const std::vector<PairEvaluation>& pairs);

} // namespace marsokhod::eval
