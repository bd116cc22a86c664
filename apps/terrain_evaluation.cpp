// `marsokhod eval terrain`: world + navigation per seed, scored against the world's ground truth
// (docs/navigation.md, "Evaluation on synthetic terrain").

#include "command.hpp"
#include "terrain_pictures.hpp"
#include "terrain_scoring.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <regex>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

struct TerrainCli {
  std::string seeds;
  int size = 256;
  std::string light = "high-sun";
  double rocks = world::TerrainSettings{}.rock_cover;
  double terrain_size = world::TerrainSettings{}.size_m;
  bool oracle = false;
  bool json = false;
  std::string pictures; ///< folder for one comparison picture per seed, empty for none
};

struct SeedRange {
  std::uint64_t first = 0;
  std::uint64_t last = 0;
};

SeedRange parse_seeds(const std::string& text) {
  static const std::regex pattern(R"(^(\d{1,18})(\.\.(\d{1,18}))?$)");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
    throw UsageError(
        fmt::format("--seeds '{}': expected A..B (e.g. 1..50) or a single seed", text));
  const std::uint64_t first = std::stoull(match[1].str());
  const std::uint64_t last = match[3].matched ? std::stoull(match[3].str()) : first;
  if (last < first)
    throw UsageError(fmt::format("--seeds '{}': the last seed is below the first", text));
  if (last - first >= 10000)
    throw UsageError(fmt::format("--seeds '{}': at most 10000 seeds at a time", text));
  return {first, last};
}

using ElevationErrors = std::array<std::vector<float>, kTerrainBands.size()>;

struct SeedOutcome {
  std::uint64_t seed = 0;
  BandTable bands{};
  BandTable hazards{};
  bool found = false;
  bool truth_found = false;
  bool unsafe = false;
  ElevationErrors elevation_errors{};
  std::string reason;
  double seconds = 0.0;
};

void write_picture(const std::string& folder, std::uint64_t seed, const TerrainComparison& site) {
  const std::filesystem::path path =
      std::filesystem::path(folder) / fmt::format("seed-{}.png", seed);
  try {
    imaging::write_image(path, terrain_comparison_picture(site).view());
  } catch (const std::exception& error) {
    throw CommandError(error.what());
  }
}

SeedOutcome evaluate_seed(std::uint64_t seed, const TerrainCli& cli) {
  world::TerrainSettings settings;
  settings.seed = seed;
  settings.rock_cover = cli.rocks;
  settings.size_m = cli.terrain_size;
  const world::Terrain terrain = world::Terrain::generate(settings);
  const world::LitSurface surface(terrain,
                                  world::lighting_preset(world::parse_light_preset(cli.light)));
  imaging::RigParameters rig_parameters;
  rig_parameters.width_px = rig_parameters.height_px = cli.size;
  const imaging::StereoRig rig(rig_parameters);
  world::RenderOptions render;
  render.noise_seed = seed;
  const world::RoverPlacement placement = world::place_rover(terrain.height, world::RoverPose{});
  const world::RenderedFrame frame =
      world::Renderer(terrain).render_with_ground_truth(rig, placement, surface, render);

  nav::NavigationOptions options;
  options.attitude = placement.attitude;
  const auto start = std::chrono::steady_clock::now();
  const nav::NavigationResult result =
      cli.oracle ? nav::navigate_disparity(frame.truth.disparity, frame.truth.valid, rig, options)
                 : nav::navigate(frame.images.left, frame.images.right, rig, options);
  SeedOutcome outcome;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.seed = seed;
  outcome.hazards = score_hazards(result.zones, frame.truth);
  outcome.found = result.found();
  outcome.reason = result.reason();
  collect_elevation_errors(result.terrain, result.zones, frame.truth, outcome.elevation_errors);

  const nav::TerrainPoints truth_terrain =
      nav::reconstruct_terrain(frame.truth.disparity, rig, placement.attitude);
  outcome.unsafe = result.found() && crosses_obstacle(result.plan, truth_terrain, frame.truth);
  const nav::ZoneMap truth_zones = ground_truth_zones(truth_terrain, frame.truth, options.zones);
  outcome.bands = score_zones(result.zones, truth_zones, frame.truth);
  const nav::PathPlan truth_plan = nav::plan_path(truth_terrain, truth_zones, options.planner);
  outcome.truth_found = truth_plan.found;
  if (!cli.pictures.empty())
    write_picture(
        cli.pictures, seed,
        {frame.images.left, result.zones, result.plan, truth_zones, truth_plan, frame.truth});
  return outcome;
}

struct Summary {
  BandTable bands{};
  BandTable hazards{};
  BandCounts near{}; // 2-10 m
  ElevationErrors elevation_errors{};
  int found = 0;
  int truth_found = 0;
  int found_where_truth = 0;
  int unsafe = 0;
  double seconds = 0.0;
};

Summary summarize(const std::vector<SeedOutcome>& outcomes) {
  Summary s;
  for (const SeedOutcome& o : outcomes) {
    for (std::size_t b = 0; b < s.bands.size(); ++b) {
      s.bands[b] += o.bands[b];
      s.hazards[b] += o.hazards[b];
    }
    s.found += o.found ? 1 : 0;
    s.truth_found += o.truth_found ? 1 : 0;
    s.found_where_truth += (o.found && o.truth_found) ? 1 : 0;
    s.unsafe += o.unsafe ? 1 : 0;
    s.seconds += o.seconds;
    for (std::size_t b = 0; b < s.elevation_errors.size(); ++b)
      s.elevation_errors[b].insert(s.elevation_errors[b].end(), o.elevation_errors[b].begin(),
                                   o.elevation_errors[b].end());
  }
  s.near = s.bands[0];
  s.near += s.bands[1];
  return s;
}

// The q-quantile (0..1) of `values`, NaN when empty; reorders `values`.
double quantile(std::vector<float>& values, double q) {
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

std::string band_name(const RangeBand& band) {
  return fmt::format("{:g}-{:g}", band.from_m, band.to_m);
}

void print_json(const TerrainCli& cli, const std::vector<SeedOutcome>& outcomes) {
  const Summary s = summarize(outcomes);
  nlohmann::ordered_json json;
  json["seeds"] = outcomes.size();
  json["size"] = cli.size;
  json["light"] = cli.light;
  json["rocks"] = cli.rocks;
  json["stereo"] = cli.oracle ? "ground truth" : "matched";
  json["obstacle_recall"] =
      number_or_null(percent(s.near.obstacles_prohibited, s.near.obstacle_pixels));
  json["false_prohibited"] = number_or_null(percent(s.near.free_prohibited, s.near.free_pixels));
  nlohmann::ordered_json causes;
  for (int z = 1; z < nav::kZoneKinds; ++z)
    causes[std::string(nav::to_string(static_cast<nav::Zone>(z)))] = number_or_null(
        percent(s.near.free_prohibited_as[static_cast<std::size_t>(z)], s.near.free_pixels));
  json["false_prohibited_by_zone"] = causes;
  json["paths_found"] = s.found;
  json["ground_truth_paths"] = s.truth_found;
  json["paths_found_where_ground_truth_has_one"] = s.found_where_truth;
  json["unsafe_paths"] = s.unsafe;
  json["navigation_seconds_per_seed"] = outcomes.empty() ? 0.0 : s.seconds / outcomes.size();
  json["bands"] = nlohmann::ordered_json::array();
  for (std::size_t b = 0; b < s.bands.size(); ++b) {
    const BandCounts& c = s.bands[b];
    json["bands"].push_back(
        {{"band_m", band_name(kTerrainBands[b])},
         {"obstacle_pixels", c.obstacle_pixels},
         {"obstacle_recall", number_or_null(percent(c.obstacles_prohibited, c.obstacle_pixels))},
         {"free_pixels", c.free_pixels},
         {"false_prohibited", number_or_null(percent(c.free_prohibited, c.free_pixels))}});
  }
  json["hazard_bands"] = nlohmann::ordered_json::array();
  for (std::size_t b = 0; b < s.hazards.size(); ++b) {
    const BandCounts& c = s.hazards[b];
    json["hazard_bands"].push_back(
        {{"band_m", band_name(kTerrainBands[b])},
         {"obstacle_recall", number_or_null(percent(c.obstacles_prohibited, c.obstacle_pixels))},
         {"false_hazard", number_or_null(percent(c.free_prohibited, c.free_pixels))}});
  }
  json["per_seed"] = nlohmann::ordered_json::array();
  for (const SeedOutcome& o : outcomes) {
    nlohmann::ordered_json entry = {{"seed", o.seed},
                                    {"found", o.found},
                                    {"ground_truth_found", o.truth_found},
                                    {"unsafe", o.unsafe}};
    if (!o.found)
      entry["reason"] = o.reason;
    json["per_seed"].push_back(entry);
  }
  fmt::print("{}\n", json.dump(2));
}

std::string shown(double value) {
  return std::isfinite(value) ? fmt::format("{:.1f}", value) : std::string("-");
}

void print_table(const TerrainCli& cli, const std::vector<SeedOutcome>& outcomes) {
  const Summary s = summarize(outcomes);
  fmt::print("{} seeds, {}x{} px, light {}, rocks {:.0f} %, {} disparity\n", outcomes.size(),
             cli.size, cli.size, cli.light, 100.0 * cli.rocks,
             cli.oracle ? "ground-truth" : "matched");
  fmt::print("{:<8} {:>12} {:>10} {:>12} {:>13}\n", "band m", "obstacle px", "recall %", "free px",
             "false proh. %");
  for (std::size_t b = 0; b < s.bands.size(); ++b) {
    const BandCounts& c = s.bands[b];
    fmt::print("{:<8} {:>12} {:>10} {:>12} {:>13}\n", band_name(kTerrainBands[b]),
               c.obstacle_pixels, shown(percent(c.obstacles_prohibited, c.obstacle_pixels)),
               c.free_pixels, shown(percent(c.free_prohibited, c.free_pixels)));
  }
  fmt::print("hazards alone (no margin) against obstacles alone, recall % / false %:");
  for (std::size_t b = 0; b < s.hazards.size(); ++b)
    fmt::print(" {} m {} / {};", band_name(kTerrainBands[b]),
               shown(percent(s.hazards[b].obstacles_prohibited, s.hazards[b].obstacle_pixels)),
               shown(percent(s.hazards[b].free_prohibited, s.hazards[b].free_pixels)));
  fmt::print("\n");
  fmt::print("2-10 m: obstacle recall {} %, false prohibition {} % (",
             shown(percent(s.near.obstacles_prohibited, s.near.obstacle_pixels)),
             shown(percent(s.near.free_prohibited, s.near.free_pixels)));
  for (int z = 1; z < nav::kZoneKinds; ++z)
    fmt::print(
        "{}{} {}", z > 1 ? ", " : "", nav::to_string(static_cast<nav::Zone>(z)),
        shown(percent(s.near.free_prohibited_as[static_cast<std::size_t>(z)], s.near.free_pixels)));
  fmt::print(")\n");
  fmt::print("paths found {} of {} seeds; ground truth has a path on {}, of which found {}; "
             "unsafe paths {}\n",
             s.found, outcomes.size(), s.truth_found, s.found_where_truth, s.unsafe);
  fmt::print("elevation error on judged free ground, cm, median / 90 % / 99 %:");
  for (std::size_t b = 0; b < s.elevation_errors.size(); ++b) {
    std::vector<float> errors = s.elevation_errors[b];
    fmt::print(" {} m {} / {} / {};", band_name(kTerrainBands[b]),
               shown(100.0 * quantile(errors, 0.5)), shown(100.0 * quantile(errors, 0.9)),
               shown(100.0 * quantile(errors, 0.99)));
  }
  fmt::print("\n");
  fmt::print("navigation {:.2f} ms per seed (host wall clock)\n",
             outcomes.empty() ? 0.0 : 1000.0 * s.seconds / outcomes.size());
}

} // namespace

Command add_terrain_evaluation(CLI::App& eval) {
  auto cli = std::make_shared<TerrainCli>();
  CLI::App* app = eval.add_subcommand(
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
      "zones and terrain; a path is unsafe when any of its pixels sees a ground-truth obstacle "
      "(not grown), or the rover's straight drive to its start does. 'Hazards alone' scores "
      "unknown, step and slope pixels against the obstacle map itself, without margins.");
  app->add_option("--seeds", cli->seeds, "Terrain seeds A..B (inclusive) or one seed")->required();
  app->add_option("--size", cli->size, "Image width and height, pixels")
      ->check(CLI::Range(32, 1024))
      ->capture_default_str();
  app->add_option("--light", cli->light, "Lighting preset")
      ->check(CLI::IsMember({"high-sun", "overexposed", "dark-wet", "low-sun"}))
      ->capture_default_str();
  app->add_option("--rocks", cli->rocks, "Fraction of the ground covered by rocks")
      ->check(CLI::Range(0.0, 0.5))
      ->capture_default_str();
  app->add_option("--terrain-size", cli->terrain_size, "Side of each square site, metres")
      ->check(CLI::Range(16.0, 200.0))
      ->capture_default_str();
  app->add_flag("--oracle", cli->oracle,
                "Navigate on the ground-truth disparity instead of matching (scores the hazard "
                "rules alone)");
  app->add_option("--pictures", cli->pictures,
                  "Folder (created if missing) for one picture per seed, seed-N.png: left image, "
                  "zones judged against ground truth, ground-truth zones");
  app->add_flag("--json", cli->json, "Print one JSON object instead of a table");
  return {app, [cli] {
            const SeedRange range = parse_seeds(cli->seeds);
            if (!cli->pictures.empty())
              prepare_output_folder(cli->pictures);
            std::vector<SeedOutcome> outcomes;
            const std::uint64_t count = range.last - range.first + 1;
            for (std::uint64_t seed = range.first; seed <= range.last; ++seed) {
              fmt::print(stderr, "seed {}/{} ({})\n", seed - range.first + 1, count, seed);
              outcomes.push_back(evaluate_seed(seed, *cli));
            }
            if (cli->json)
              print_json(*cli, outcomes);
            else
              print_table(*cli, outcomes);
            return static_cast<int>(kSuccess);
          }};
}

} // namespace marsokhod::apps
