// `marsokhod eval stereo PAIRS`: the options of the stereo evaluation, and its table or JSON.

#include "cli/command.hpp"
#include "cli/option_checks.hpp"

#include "marsokhod/eval/stereo/stereo_evaluation.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

nlohmann::ordered_json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

std::string optional_text(const std::optional<double>& value) {
  return value ? fmt::format("{:.2f}", *value) : std::string("-");
}

void print_stereo_json(const std::vector<eval::PairEvaluation>& pairs) {
  nlohmann::ordered_json json;
  json["pairs"] = nlohmann::ordered_json::array();
  for (const eval::PairEvaluation& pair : pairs) {
    nlohmann::ordered_json entry = {{"name", pair.name},
                                    {"bad_percent", optional_json(pair.bad_percent)}};
    if (pair.bad_percent_nonocc)
      entry["bad_percent_nonocc"] = *pair.bad_percent_nonocc;
    entry["seconds"] = pair.seconds;
    entry["valid_percent"] = pair.valid_percent;
    entry["max_disparity"] = pair.max_disparity;
    if (!pair.note.empty())
      entry["note"] = pair.note;
    json["pairs"].push_back(entry);
  }
  json["mean_bad_percent"] = optional_json(eval::mean_bad_percent(pairs));
  fmt::print("{}\n", json.dump(2));
}

void print_stereo_table(const std::vector<eval::PairEvaluation>& pairs) {
  fmt::print("{:<10} {:>10} {:>6} {:>10} {:>9} {:>8} {:>9}  {}\n", "pair", "size", "max d",
             "bad-1.0 %", "nonocc %", "valid %", "seconds", "note");
  for (const eval::PairEvaluation& pair : pairs)
    fmt::print("{:<10} {:>10} {:>6} {:>10} {:>9} {:>8.1f} {:>9.4f}  {}\n", pair.name,
               fmt::format("{}x{}", pair.width, pair.height), pair.max_disparity,
               optional_text(pair.bad_percent), optional_text(pair.bad_percent_nonocc),
               pair.valid_percent, pair.seconds, pair.note);
  fmt::print("mean bad-1.0 % over the pairs with ground truth: {}\n",
             optional_text(eval::mean_bad_percent(pairs)));
}

struct StereoCli {
  eval::StereoEvaluationOptions evaluation;
  bool json = false;
  std::string feature{nav::to_string(nav::StereoOptions{}.feature)};
  std::string fill{nav::to_string(nav::StereoOptions{}.fill)};
};

} // namespace

Command add_stereo_evaluation(CLI::App& parent) {
  auto cli = std::make_shared<StereoCli>();
  eval::StereoEvaluationOptions& options = cli->evaluation;
  options.stereo.ground_prior = false; // Middlebury scenes are not views of the ground
  CLI::App* app = parent.add_subcommand(
      "stereo", "Bad-1.0 % and time of the stereo matcher on the pairs of a PAIRS.tsv index.");
  app->add_option("PAIRS", options.index,
                  "Tab-separated pair index (docs/formats.md, \"Stereo pair index\")")
      ->required();
  app->add_flag("--json", cli->json, "Print one JSON object instead of a table");
  app->add_option("--out", options.out_dir,
                  "Write <pair>_disparity.pfm and a false-colour .png per pair here");
  app->add_option("--max-disparity", options.fallback_max_disparity,
                  "Search range of pairs whose index gives no largest disparity")
      ->transform(integer_between(1, 4096))
      ->capture_default_str();
  app->add_option("--feature", cli->feature, "Brightness feature: census3x3, census5x5, rank5x5")
      ->check(CLI::IsMember({"census3x3", "census5x5", "rank5x5"}))
      ->capture_default_str();
  app->add_option("--levels", options.stereo.pyramid_levels, "Pyramid layers (0 = automatic)")
      ->transform(integer_between(0, nav::kMaxPyramidLevels))
      ->capture_default_str();
  app->add_option("--band", options.stereo.search_band,
                  "Search band around the coarse estimate, px")
      ->transform(integer_between(0, 64))
      ->capture_default_str();
  app->add_option("--fill", cli->fill, "Fill policy of unreliable pixels: background or none")
      ->check(CLI::IsMember({"background", "none"}))
      ->capture_default_str();
  app->add_option("--right-gain", options.right_gain, "Multiply every right image by this first")
      ->check(real_between(0.01, 100.0));
  app->add_option("--right-offset", options.right_offset, "Then add this grey level")
      ->check(real_between(-255.0, 255.0));
  return {app, [cli] {
            cli->evaluation.stereo.feature = *nav::parse_feature_kind(cli->feature);
            cli->evaluation.stereo.fill = *nav::parse_fill_policy(cli->fill);
            const std::vector<eval::PairEvaluation> pairs =
                eval::evaluate_stereo_pairs(cli->evaluation);
            if (cli->json)
              print_stereo_json(pairs);
            else
              print_stereo_table(pairs);
            return static_cast<int>(kSuccess);
          }};
}

} // namespace marsokhod::apps
