// `marsokhod eval terrain`: its options, the evaluation on synthetic terrain, its table or JSON.

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "navigation/seed_option.hpp"

#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/eval/terrain/terrain_figures.hpp"
#include "marsokhod/io/files/file_writer.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

struct TerrainCli {
  std::string seeds;
  std::string target = "10..12";
  eval::TerrainEvaluationOptions evaluation;
  bool json = false;
};

// Nearest and farthest destination the planner takes, "A..B" in metres.
constexpr double kNearestTarget = 1.0;
constexpr double kFarthestTarget = 20.0; // the zones judge no point beyond 20 m

void read_target_band(const std::string& text, eval::TerrainEvaluationOptions& evaluation) {
  const auto band = real_band(text, kNearestTarget, kFarthestTarget);
  if (!band)
    throw UsageError(fmt::format("--target '{}': write A..B in metres, {} <= A <= B <= {} (the "
                                 "paper's band is 10..12)",
                                 text, kNearestTarget, kFarthestTarget));
  evaluation.target_min_m = band->first;
  evaluation.target_max_m = band->second;
}

nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json figures_json(const eval::TerrainEvaluationOptions& options,
                                    const eval::TerrainFigures& f,
                                    const std::vector<eval::SeedOutcome>& outcomes) {
  nlohmann::ordered_json json;
  json["seeds"] = f.seeds;
  json["size"] = options.size;
  json["light"] = options.light;
  json["rocks"] = options.rocks;
  json["stereo"] = options.oracle ? "ground truth" : "matched";
  json["target_m"] = {options.target_min_m, options.target_max_m};
  json["step_baseline_m"] = options.step_baseline_m;
  json["unseen_cell_m"] = options.unseen_cell_m;
  json["obstacle_recall"] = number_or_null(f.obstacle_recall);
  json["false_prohibited"] = number_or_null(f.false_prohibited);
  nlohmann::ordered_json causes;
  for (int z = 1; z < nav::kZoneKinds; ++z)
    causes[std::string(nav::to_string(static_cast<nav::Zone>(z)))] =
        number_or_null(f.false_prohibited_by_zone[static_cast<std::size_t>(z)]);
  json["false_prohibited_by_zone"] = causes;
  json["paths_found"] = f.paths_found;
  json["ground_truth_paths"] = f.ground_truth_paths;
  json["paths_found_where_ground_truth_has_one"] = f.paths_found_where_ground_truth_has_one;
  json["unsafe_paths"] = f.unsafe_paths;
  json["unsafe_paths_pixel_rule"] = f.unsafe_paths_pixel_rule;
  json["navigation_seconds_per_seed"] = f.navigation_seconds_per_seed;
  json["bands"] = nlohmann::ordered_json::array();
  for (const eval::BandFigures& b : f.bands)
    json["bands"].push_back({{"band_m", b.band_m},
                             {"obstacle_pixels", b.obstacle_pixels},
                             {"obstacle_recall", number_or_null(b.obstacle_recall)},
                             {"free_pixels", b.free_pixels},
                             {"false_prohibited", number_or_null(b.false_prohibited)}});
  json["hazard_bands"] = nlohmann::ordered_json::array();
  for (const eval::BandFigures& b : f.bands)
    json["hazard_bands"].push_back({{"band_m", b.band_m},
                                    {"obstacle_recall", number_or_null(b.hazard_recall)},
                                    {"false_hazard", number_or_null(b.false_hazard)}});
  json["per_seed"] = nlohmann::ordered_json::array();
  for (const eval::SeedOutcome& o : outcomes) {
    nlohmann::ordered_json entry = {{"seed", o.seed},
                                    {"found", o.found},
                                    {"ground_truth_found", o.truth_found},
                                    {"unsafe", o.unsafe},
                                    {"unsafe_pixel_rule", o.unsafe_pixel_rule}};
    if (!o.found)
      entry["reason"] = o.reason;
    if (o.unsafe_hit)
      entry["unsafe_because"] = eval::describe(*o.unsafe_hit);
    json["per_seed"].push_back(entry);
  }
  return json;
}

std::string shown(double value) {
  return std::isfinite(value) ? fmt::format("{:.1f}", value) : std::string("-");
}

void print_unsafe(const std::vector<eval::SeedOutcome>& outcomes) {
  for (const eval::SeedOutcome& o : outcomes)
    if (o.unsafe_hit)
      fmt::print("unsafe: seed {}: {}\n", o.seed, eval::describe(*o.unsafe_hit));
}

void print_table(const eval::TerrainEvaluationOptions& options, const eval::TerrainFigures& f,
                 const std::vector<eval::SeedOutcome>& outcomes) {
  fmt::print("{} seeds, {}x{} px, light {}, rocks {:.0f} %, {} disparity\n", f.seeds, options.size,
             options.size, options.light, 100.0 * options.rocks,
             options.oracle ? "ground-truth" : "matched");
  fmt::print(
      "paths to {:g}..{:g} m, step window {:g} m, {}\n", options.target_min_m, options.target_max_m,
      options.step_baseline_m,
      options.unseen_cell_m > 0.0
          ? fmt::format("footprint kept on ground seen in {:g} m cells", options.unseen_cell_m)
          : std::string("footprint may cross unseen ground"));
  fmt::print("{:<8} {:>12} {:>10} {:>12} {:>13}\n", "band m", "obstacle px", "recall %", "free px",
             "false proh. %");
  for (const eval::BandFigures& b : f.bands)
    fmt::print("{:<8} {:>12} {:>10} {:>12} {:>13}\n", b.band_m, b.obstacle_pixels,
               shown(b.obstacle_recall), b.free_pixels, shown(b.false_prohibited));
  fmt::print("hazards alone (no margin) against obstacles alone, recall % / false %:");
  for (const eval::BandFigures& b : f.bands)
    fmt::print(" {} m {} / {};", b.band_m, shown(b.hazard_recall), shown(b.false_hazard));
  fmt::print("\n");
  fmt::print("2-10 m: obstacle recall {} %, false prohibition {} % (", shown(f.obstacle_recall),
             shown(f.false_prohibited));
  for (int z = 1; z < nav::kZoneKinds; ++z)
    fmt::print("{}{} {}", z > 1 ? ", " : "", nav::to_string(static_cast<nav::Zone>(z)),
               shown(f.false_prohibited_by_zone[static_cast<std::size_t>(z)]));
  fmt::print(")\n");
  fmt::print("paths found {} of {} seeds; ground truth has a path on {}, of which found {}; "
             "unsafe paths {} (footprint; {} by the one-pixel line)\n",
             f.paths_found, f.seeds, f.ground_truth_paths, f.paths_found_where_ground_truth_has_one,
             f.unsafe_paths, f.unsafe_paths_pixel_rule);
  print_unsafe(outcomes);
  fmt::print("elevation error on judged free ground, cm, median / 90 % / 99 %:");
  for (const eval::BandFigures& b : f.bands)
    fmt::print(" {} m {} / {} / {};", b.band_m, shown(b.elevation_error_cm[0]),
               shown(b.elevation_error_cm[1]), shown(b.elevation_error_cm[2]));
  fmt::print("\n");
  fmt::print("navigation {:.2f} ms per seed (host wall clock)\n", f.navigation_ms_per_seed);
}

} // namespace

Command add_terrain_evaluation(CLI::App& parent) {
  auto cli = std::make_shared<TerrainCli>();
  CLI::App* app = parent.add_subcommand(
      "terrain", "Render synthetic sites, navigate, and score the prohibited zones and paths "
                 "against ground truth.");
  app->footer(
      "Scoring: the ground-truth zones are the world's obstacle map at each pixel both cameras "
      "see, "
      "grown by the rover's half-width on the same ground grid the navigation grows its own "
      "(pixels the two cameras do not both see are unknown). Over the pixels both cameras see, by "
      "true "
      "ground range: obstacle recall = ground-truth obstacle pixels the navigation prohibits "
      "(any zone but traversable); false prohibition = pixels traversable in the ground-truth "
      "zones that the navigation prohibits (free pixels inside the truth's margin are not "
      "scored). 'Ground truth has a path' = the same planner finds one on the ground-truth "
      "zones and terrain. A path is unsafe when the rover's footprint (1.85 m x 1.20 m, the "
      "chassis in docs/navigation.md), driven along its commands from the rover's centre on the "
      "true ground, turns included, covers a node of the world's obstacle map; the old rule "
      "(a path pixel, or a pixel of the straight drive to its start, sees an obstacle) is "
      "reported beside it as the one-pixel line. 'Hazards alone' scores "
      "unknown, step and slope pixels against the obstacle map itself, without margins.");
  app->add_option("--seeds", cli->seeds, "Terrain seeds A..B (inclusive) or one seed")->required();
  app->add_option("--size", cli->evaluation.size, "Image width and height, pixels")
      ->transform(integer_between(32, 1024))
      ->capture_default_str();
  app->add_option("--light", cli->evaluation.light, "Lighting preset")
      ->check(CLI::IsMember({"high-sun", "overexposed", "dark-wet", "low-sun"}))
      ->capture_default_str();
  app->add_option("--rocks", cli->evaluation.rocks, "Fraction of the ground covered by rocks")
      ->check(real_between(0.0, 0.5))
      ->capture_default_str();
  app->add_option("--terrain-size", cli->evaluation.terrain_size,
                  "Side of each square site, metres")
      ->check(real_between(16.0, 200.0))
      ->capture_default_str();
  app->add_option("--unseen-cell", cli->evaluation.unseen_cell_m,
                  "Keep the footprint on ground the pair saw, judged on a grid of this cell, "
                  "metres (0: the footprint may cross unseen ground)")
      ->check(real_between(0.0, 2.0))
      ->capture_default_str();
  app->add_option("--step-baseline", cli->evaluation.step_baseline_m,
                  "The zones' step window, metres (the world judges steps over 0.30)")
      ->check(real_between(0.05, 1.0))
      ->capture_default_str();
  app->add_option("--target", cli->target,
                  "Band the path's destination lies in, A..B metres (the paper's 10..12)")
      ->capture_default_str();
  app->add_flag("--oracle", cli->evaluation.oracle,
                "Navigate on the ground-truth disparity instead of matching (scores the hazard "
                "rules alone)");
  app->add_option("--pictures", cli->evaluation.pictures,
                  "Folder (created if missing) for one picture per seed, seed-N.png: left image, "
                  "zones judged against ground truth, ground-truth zones; and terrain.json, the "
                  "figures as --json prints them");
  app->add_flag("--json", cli->json, "Print one JSON object instead of a table");
  return {app, [cli] {
            const eval::SeedRange range = seed_range_option(cli->seeds);
            read_target_band(cli->target, cli->evaluation);
            const std::vector<eval::SeedOutcome> outcomes = eval::evaluate_seeds(
                range, cli->evaluation,
                [](std::uint64_t position, std::uint64_t count, std::uint64_t seed) {
                  fmt::print(stderr, "seed {}/{} ({})\n", position, count, seed);
                });
            const eval::TerrainFigures figures = eval::terrain_figures(outcomes);
            const nlohmann::ordered_json json = figures_json(cli->evaluation, figures, outcomes);
            // The pictures' folder holds the figures too: `report` reads it by them.
            if (!cli->evaluation.pictures.empty())
              io::write_file_atomically(fs::path(cli->evaluation.pictures) / "terrain.json",
                                        json.dump(2) + "\n");
            if (cli->json)
              fmt::print("{}\n", json.dump(2));
            else
              print_table(cli->evaluation, figures, outcomes);
            return static_cast<int>(kSuccess);
          }};
}

} // namespace marsokhod::apps
