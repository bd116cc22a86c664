// Stereo evaluation: reading each pair and its ground truth, matching, timing and scoring.
#include "marsokhod/eval/stereo/stereo_evaluation.hpp"

#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/stereo/stereo_pairs.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/imaging/pictures/colormap.hpp"
#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/paths/contained_path.hpp"
#include "marsokhod/nav/stereo/disparity_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <variant>

namespace marsokhod::eval {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const StereoEvaluationOptions& options, const StereoPairEntry& entry,
                       const std::string& problem) {
  throw EvaluationError(fmt::format("{}:{}: {}", options.index, entry.line, problem));
}

template <class T>
void require_size(const StereoEvaluationOptions& options, const StereoPairEntry& entry,
                  const imaging::Image<T>& image, const fs::path& file) {
  if (image.width() != entry.width || image.height() != entry.height)
    fail(options, entry,
         fmt::format("{} is {}x{} but the index says {}x{}", file.string(), image.width(),
                     image.height(), entry.width, entry.height));
}

// Image errors name the file; the index line is added so the user knows which entry it was.
template <class Read>
auto read_for_entry(const StereoEvaluationOptions& options, const StereoPairEntry& entry,
                    Read read) {
  try {
    return read();
  } catch (const imaging::ImageError& error) {
    fail(options, entry, error.what());
  }
}

imaging::Image<std::uint8_t> read_grey(const StereoEvaluationOptions& options,
                                       const StereoPairEntry& entry, const fs::path& file) {
  imaging::Image<std::uint8_t> image =
      read_for_entry(options, entry, [&] { return imaging::read_gray8(file); });
  require_size(options, entry, image, file);
  return image;
}

// value / scale, with 0 (unknown) kept as 0.
template <class T>
imaging::Image<float> truth_disparity(const imaging::Image<T>& stored, double scale) {
  imaging::Image<float> truth(stored.width(), stored.height());
  for (std::size_t i = 0; i < stored.size(); ++i)
    truth.data()[i] = static_cast<float>(static_cast<double>(stored.data()[i]) / scale);
  return truth;
}

imaging::Image<float> read_truth(const StereoEvaluationOptions& options,
                                 const StereoPairEntry& entry) {
  const fs::path& file = *entry.truth;
  const imaging::AnyImage stored =
      read_for_entry(options, entry, [&] { return imaging::read_image(file); });
  if (const auto* bytes = std::get_if<imaging::Image<std::uint8_t>>(&stored);
      bytes && entry.truth_bits == 8) {
    require_size(options, entry, *bytes, file);
    return truth_disparity(*bytes, entry.truth_scale);
  }
  if (const auto* words = std::get_if<imaging::Image<std::uint16_t>>(&stored);
      words && entry.truth_bits == 16) {
    require_size(options, entry, *words, file);
    return truth_disparity(*words, entry.truth_scale);
  }
  fail(options, entry,
       fmt::format("{} is not a one-channel {}-bit image as gt_bits says", file.string(),
                   entry.truth_bits));
}

void distort(imaging::Image<std::uint8_t>& image, double gain, double offset) {
  if (gain == 1.0 && offset == 0.0)
    return;
  for (std::size_t i = 0; i < image.size(); ++i)
    image.data()[i] = static_cast<std::uint8_t>(
        std::clamp(std::lround(gain * image.data()[i] + offset), 0L, 255L));
}

int search_range(const StereoEvaluationOptions& options, const StereoPairEntry& entry) {
  // The reader bounds max_gt_disp_px to (0, kMaxImageSide], so the rounded value fits an int.
  const int range = entry.max_truth_disparity
                        ? static_cast<int>(std::ceil(*entry.max_truth_disparity))
                        : options.fallback_max_disparity;
  if (range < 1 || range >= entry.width)
    fail(options, entry,
         fmt::format("search range {} px{} does not fit in an image {} px wide", range,
                     entry.max_truth_disparity ? "" : " (--max-disparity)", entry.width));
  return range;
}

fs::path output_path(const fs::path& dir, const std::string& file) {
  try {
    return io::path_inside(dir, file, "output file");
  } catch (const io::InputError& error) {
    throw EvaluationError(error.what());
  }
}

void write_outputs(const StereoEvaluationOptions& options, const std::string& name,
                   const imaging::Image<float>& disparity) {
  const fs::path dir = options.out_dir;
  // The names come from the index; the reader refuses any that could leave the folder, and
  // path_inside makes sure of it here, where they become paths.
  const fs::path pfm = output_path(dir, name + "_disparity.pfm");
  const fs::path png = output_path(dir, name + "_disparity.png");
  imaging::prepare_output_folder(dir);
  imaging::write_image(pfm, disparity.view());
  imaging::ColormapOptions colour;
  colour.min_value = 0.0F;
  colour.unit = "px";
  colour.title = "disparity";
  imaging::write_image(png, imaging::false_colour(disparity.view(), colour).view());
}

// The matcher refuses options that do not suit this pair (more pyramid layers than its size
// allows); the message then says which pair of the index it was.
nav::StereoResult match(const StereoEvaluationOptions& options, const StereoPairEntry& entry,
                        const imaging::Image<std::uint8_t>& left,
                        const imaging::Image<std::uint8_t>& right,
                        const nav::StereoOptions& stereo) {
  try {
    return nav::match_stereo(left.view(), right.view(), stereo);
  } catch (const std::invalid_argument& error) {
    fail(options, entry, fmt::format("{}: {}", entry.left.string(), error.what()));
  }
}

PairEvaluation evaluate(const StereoEvaluationOptions& options, const StereoPairEntry& entry) {
  const imaging::Image<std::uint8_t> left = read_grey(options, entry, entry.left);
  imaging::Image<std::uint8_t> right = read_grey(options, entry, entry.right);
  distort(right, options.right_gain, options.right_offset);
  PairEvaluation pair;
  pair.name = entry.name;
  pair.width = entry.width;
  pair.height = entry.height;
  pair.max_disparity = search_range(options, entry);
  nav::StereoOptions stereo = options.stereo;
  stereo.max_disparity = pair.max_disparity;
  const auto start = std::chrono::steady_clock::now();
  const nav::StereoResult result = match(options, entry, left, right, stereo);
  pair.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  pair.valid_percent = 100.0 * static_cast<double>(result.valid_pixels) /
                       static_cast<double>(entry.width * entry.height);
  pair.note = result.reason;
  if (!options.out_dir.empty())
    write_outputs(options, entry.name, result.disparity);
  if (!entry.truth) {
    pair.note = "no ground truth: timed only";
    return pair;
  }
  const imaging::Image<float> truth = read_truth(options, entry);
  pair.bad_percent =
      nav::score_bad_pixels(result.disparity.view(), truth.view(), {}, 1.0F).percent();
  // The non-occlusion mask, when present, sits beside the ground truth as <name>_nonocc.pgm.
  const fs::path mask_file = entry.truth->parent_path() / (entry.name + "_nonocc.pgm");
  if (fs::is_regular_file(mask_file)) {
    const imaging::Image<std::uint8_t> mask = read_grey(options, entry, mask_file);
    pair.bad_percent_nonocc =
        nav::score_bad_pixels(result.disparity.view(), truth.view(), mask.view(), 1.0F).percent();
  }
  return pair;
}

} // namespace

std::vector<PairEvaluation> evaluate_stereo_pairs(const StereoEvaluationOptions& options) {
  std::vector<PairEvaluation> pairs;
  for (const StereoPairEntry& entry : read_stereo_pairs(options.index))
    pairs.push_back(evaluate(options, entry));
  return pairs;
}

std::optional<double> mean_bad_percent(const std::vector<PairEvaluation>& pairs) {
  double sum = 0.0;
  int scored = 0;
  for (const PairEvaluation& pair : pairs)
    if (pair.bad_percent) {
      sum += *pair.bad_percent;
      ++scored;
    }
  if (scored == 0)
    return std::nullopt;
  return sum / scored;
}

} // namespace marsokhod::eval
