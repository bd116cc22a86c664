// Evaluation on synthetic terrain: world + navigation per seed, scored against ground truth.
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"

#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/terrain/terrain_pictures.hpp"
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/render/renderer.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <optional>
#include <string_view>

namespace marsokhod::eval {
namespace {

void write_picture(const std::string& folder, std::uint64_t seed, const TerrainComparison& site) {
  const std::filesystem::path path =
      std::filesystem::path(folder) / fmt::format("seed-{}.png", seed);
  try {
    imaging::write_image(path, terrain_comparison_picture(site).view());
  } catch (const std::exception& error) {
    throw EvaluationError(error.what());
  }
}

bool seen_by_both(const imaging::StereoRig& rig, const Eigen::Vector3d& point) {
  for (const imaging::Eye eye : {imaging::Eye::left, imaging::Eye::right}) {
    const std::optional<Eigen::Vector2d> pixel = rig.project(eye, point);
    if (!pixel || pixel->x() < 0.0 || pixel->y() < 0.0 ||
        pixel->x() > rig.parameters().width_px - 1.0 ||
        pixel->y() > rig.parameters().height_px - 1.0)
      return false;
  }
  return true;
}

// What the navigation made of the obstacle node the footprint met: the zone of the left-image
// pixel it projects to, unless that pixel sees something nearer.
std::string seen_as(const FootprintHit& hit, const nav::ZoneMap& zones,
                    const nav::TerrainPoints& truth, const imaging::StereoRig& rig,
                    const imaging::Attitude& attitude) {
  const std::optional<Eigen::Vector2d> pixel =
      rig.project(imaging::Eye::left, Eigen::Vector3d(hit.x_m, hit.y_m, hit.z_m), attitude);
  if (!pixel)
    return "behind the left camera";
  const int x = static_cast<int>(std::lround(pixel->x()));
  const int y = static_cast<int>(std::lround(pixel->y()));
  if (x < 0 || y < 0 || x >= zones.width() || y >= zones.height())
    return "outside the view";
  const double seen_range = truth.range(x, y);
  const double node_range = std::hypot(hit.x_m, hit.y_m);
  if (std::isfinite(seen_range) && seen_range < node_range - 0.15)
    return fmt::format("hidden from the left camera by ground {:.2f} m away", seen_range);
  return fmt::format("{} at pixel ({}, {})", nav::to_string(zones.at(x, y)), x, y);
}

} // namespace

double unseen_start_radius(const imaging::StereoRig& rig, const imaging::Chassis& chassis) {
  constexpr double kStep = 0.05;
  constexpr double kLookAhead = 20.0;
  const double half_width = 0.5 * chassis.width_m();
  double hidden_to = 0.0;
  for (double x = 0.0; x <= kLookAhead; x += kStep)
    for (const double y : {-half_width, 0.0, half_width})
      if (!seen_by_both(rig, Eigen::Vector3d(x, y, 0.0)))
        hidden_to = x + kStep;
  const double radius =
      std::hypot(hidden_to, half_width) + world::LocomotionLimits{}.step_baseline_m;
  return std::max(radius, world::TerrainSettings{}.clear_radius_m);
}

SeedRange parse_seed_range(const std::string& text, std::uint64_t max_seeds) {
  const std::size_t dots = text.find("..");
  const std::string_view whole(text);
  const std::optional<std::uint64_t> first =
      io::parse_integer<std::uint64_t>(whole.substr(0, dots));
  const std::optional<std::uint64_t> last =
      dots == std::string::npos ? first : io::parse_integer<std::uint64_t>(whole.substr(dots + 2));
  if (!first || !last)
    throw OptionError(fmt::format("'{}': expected A..B (e.g. 1..50) or a single seed, each a whole "
                                  "number from 0 to {}",
                                  text, std::numeric_limits<std::uint64_t>::max()));
  if (*last < *first)
    throw OptionError(fmt::format("'{}': the last seed is below the first", text));
  if (*last - *first >= max_seeds)
    throw OptionError(fmt::format("'{}': at most {} seeds at a time", text, max_seeds));
  return {*first, *last};
}

SeedOutcome evaluate_seed(std::uint64_t seed, const TerrainEvaluationOptions& cli) {
  world::TerrainSettings settings;
  settings.seed = seed;
  settings.rock_cover = cli.rocks;
  settings.size_m = cli.terrain_size;
  imaging::RigParameters rig_parameters;
  rig_parameters.width_px = rig_parameters.height_px = cli.size;
  const imaging::StereoRig rig(rig_parameters);
  settings.clear_radius_m = unseen_start_radius(rig);
  const world::Terrain terrain = world::Terrain::generate(settings);
  const world::LitSurface surface(terrain,
                                  world::lighting_preset(world::parse_light_preset(cli.light)));
  world::RenderOptions render;
  render.noise_seed = seed;
  const world::RoverPlacement placement = world::place_rover(terrain.height, world::RoverPose{});
  const world::RenderedFrame frame =
      world::Renderer(terrain).render_with_ground_truth(rig, placement, surface, render);

  nav::NavigationOptions options;
  options.attitude = placement.attitude;
  options.footprint.unseen_cell_m = cli.unseen_cell_m;
  options.zones.step_baseline_m = cli.step_baseline_m;
  options.planner.target_min_m = cli.target_min_m;
  options.planner.target_max_m = cli.target_max_m;
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
  outcome.unsafe_pixel_rule =
      result.found() && crosses_obstacle(result.plan, truth_terrain, frame.truth);
  if (result.found())
    outcome.unsafe_hit = judge_footprint(terrain, placement, result.drive.commands).hit;
  outcome.unsafe = outcome.unsafe_hit.has_value();
  if (outcome.unsafe_hit)
    outcome.unsafe_hit->seen_as =
        seen_as(*outcome.unsafe_hit, result.zones, truth_terrain, rig, placement.attitude);
  nav::ZoneMap truth_zones = ground_truth_zones(truth_terrain, frame.truth, options.zones);
  outcome.bands = score_zones(result.zones, truth_zones, frame.truth);
  // The navigation's own planner, its footprint check included, on what a perfect pair shows.
  const nav::PathPlan truth_plan = nav::plan_cycle_path(truth_terrain, truth_zones, options.planner,
                                                        options.drive, options.footprint);
  outcome.truth_found = truth_plan.found;
  if (!cli.pictures.empty())
    write_picture(cli.pictures, seed,
                  {frame.images.left, result.zones, result.plan, truth_zones, truth_plan,
                   frame.truth, rig, placement.attitude, outcome.unsafe_hit});
  return outcome;
}

std::vector<SeedOutcome> evaluate_seeds(const SeedRange& range,
                                        const TerrainEvaluationOptions& options,
                                        const SeedProgress& progress) {
  if (!options.pictures.empty())
    imaging::prepare_output_folder(options.pictures);
  std::vector<SeedOutcome> outcomes;
  const std::uint64_t count = range.last - range.first + 1;
  // Counted, not compared with range.last: a range ending at the largest seed must not wrap.
  for (std::uint64_t position = 1; position <= count; ++position) {
    const std::uint64_t seed = range.first + (position - 1);
    if (progress)
      progress(position, count, seed);
    outcomes.push_back(evaluate_seed(seed, options));
  }
  return outcomes;
}

} // namespace marsokhod::eval
