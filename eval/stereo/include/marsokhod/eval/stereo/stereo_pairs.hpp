// Reading a stereo-pair index (PAIRS.tsv): pair names, image files and ground-truth encodings.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// One line of a stereo-pair index (docs/formats.md, "Stereo pair index"): paths are resolved
/// against the index's folder.
struct StereoPairEntry {
  std::string name;
  std::filesystem::path left;
  std::filesystem::path right;
  std::optional<std::filesystem::path> truth; ///< ground-truth disparity image, if any
  double truth_scale = 1.0;                   ///< disparity = stored value / scale
  int truth_bits = 8;
  int width = 0;
  int height = 0;
  std::optional<double> max_truth_disparity;
  int line = 0; ///< line number in the index, for messages
};

/// Reads a tab-separated index whose header names at least the columns name, left, right, gt,
/// gt_scale, gt_bits, width, height and max_gt_disp_px (a header may carry a note in
/// parentheses, e.g. "gt_scale(disp=value/scale)"; other columns are ignored). "-" marks a
/// missing ground truth. The index is read through io's bounded reader (a regular file of at
/// most 16 MiB) and its numbers through io's checked conversions. Throws EvaluationError
/// naming the file, the line and the problem: missing columns, numbers that are not finite or
/// out of their range, pair names that are repeated or could leave an output folder, image
/// paths that are not regular files.
std::vector<StereoPairEntry> read_stereo_pairs(const std::filesystem::path& index);

} // namespace marsokhod::eval
