// `marsokhod world`: renders a synthetic stereo pair with ground truth into a folder.

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "navigation/world_report.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/scene/scene.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// Clearance the chassis needs from the terrain border, metres.
constexpr double kBorderClearance = 2.0;
/// Half the largest --terrain-size: no position beyond can be inside a terrain.
constexpr double kMaxPositionM = 100.0;
/// The rig file's limit on a misalignment angle (docs/formats.md, "Rig files").
constexpr double kMaxMisalignmentArcsec = 3600.0;

struct WorldOptions {
  std::uint64_t seed = 1;
  std::optional<int> size;
  fs::path out;
  std::string light = "high-sun";
  double rocks = world::TerrainSettings{}.rock_cover;
  double terrain_size = world::TerrainSettings{}.size_m;
  world::RoverPose pose;
  double noise = world::RenderOptions{}.noise_sigma;
  std::optional<double> pan, tilt, roll;
  std::optional<fs::path> rig_file;
  bool json = false;
};

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

imaging::RigParameters rig_parameters(const WorldOptions& o) {
  imaging::RigParameters rig =
      o.rig_file ? imaging::StereoRig::load(*o.rig_file).parameters() : imaging::RigParameters{};
  if (o.size)
    rig.width_px = rig.height_px = *o.size;
  rig.right_misalignment.pan_arcsec = o.pan.value_or(rig.right_misalignment.pan_arcsec);
  rig.right_misalignment.tilt_arcsec = o.tilt.value_or(rig.right_misalignment.tilt_arcsec);
  rig.right_misalignment.roll_arcsec = o.roll.value_or(rig.right_misalignment.roll_arcsec);
  try {
    return imaging::StereoRig(rig).parameters();
  } catch (const imaging::RigError& e) {
    throw UsageError(fmt::format("invalid option value: {}", e.what()));
  }
}

void check_pose(const WorldOptions& o) {
  const double reach = 0.5 * o.terrain_size - kBorderClearance;
  if (std::abs(o.pose.x) > reach || std::abs(o.pose.y) > reach)
    throw UsageError(fmt::format("--x/--y: ({}, {}) is too close to the edge of the {} m terrain; "
                                 "use |x|, |y| <= {} m",
                                 o.pose.x, o.pose.y, o.terrain_size, reach));
}

int run_world(const WorldOptions& o) {
  world::SceneDescription scene;
  scene.rig = rig_parameters(o);
  scene.lighting = world::lighting_preset(world::parse_light_preset(o.light));
  scene.terrain.seed = o.seed;
  scene.terrain.rock_cover = o.rocks;
  scene.terrain.size_m = o.terrain_size;
  scene.render.noise_sigma = o.noise;
  scene.render.noise_seed = o.seed;
  check_pose(o);
  try {
    world::create_scene_folder(o.out); // fail before the slow steps
  } catch (const std::exception& e) {
    throw CommandError(e.what());
  }

  fmt::print(stderr, "generating a {} m terrain at {} cm (seed {})...\n", scene.terrain.size_m,
             100.0 * scene.terrain.cell_m, o.seed);
  auto start = Clock::now();
  const world::Terrain terrain = world::Terrain::generate(scene.terrain, scene.limits);
  const double terrain_ms = elapsed_ms(start);
  fmt::print(stderr, "lighting ({}) and acceleration structure...\n", scene.lighting.name);
  start = Clock::now();
  const world::LitSurface surface(terrain, scene.lighting);
  const world::Renderer renderer(terrain);
  const double prepare_ms = elapsed_ms(start);
  start = Clock::now();
  scene.placement = world::place_rover(terrain.height, o.pose);
  const world::RenderedFrame frame = renderer.render_with_ground_truth(
      imaging::StereoRig(scene.rig), scene.placement, surface, scene.render);
  const double render_ms = elapsed_ms(start);
  start = Clock::now();
  try {
    world::write_scene(o.out, frame, scene);
  } catch (const std::exception& e) {
    throw CommandError(e.what());
  }
  const double write_ms = elapsed_ms(start);

  if (o.json) {
    print_world_json(scene, o.seed, o.out);
    return kSuccess;
  }
  print_world_summary(
      scene, o.seed, o.out,
      fmt::format("terrain {:.0f} ms, lighting and acceleration {:.0f} ms, render {:.0f} "
                  "ms, files {:.0f} ms",
                  terrain_ms, prepare_ms, render_ms, write_ms));
  return kSuccess;
}

} // namespace

Command make_world_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "world", "Render a synthetic Mars stereo pair with exact ground truth (disparity, range, "
               "elevation, visibility, obstacles) into a folder.");
  auto o = std::make_shared<WorldOptions>();
  app->add_option("--seed", o->seed, "Seed of the terrain and the sensor noise")
      ->transform(integer_between<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  app->add_option("--size", o->size, "Image width and height in pixels (the paper: 128 or 256)")
      ->transform(integer_between(16, 2048));
  app->add_option("--out", o->out, "Output folder (created if missing)")->required();
  app->add_option("--light", o->light, "Lighting preset")
      ->check(CLI::IsMember({"high-sun", "overexposed", "dark-wet", "low-sun"}))
      ->capture_default_str();
  app->add_option("--rocks", o->rocks, "Fraction of the ground covered by rocks")
      ->check(real_between(0.0, 0.5))
      ->capture_default_str();
  app->add_option("--terrain-size", o->terrain_size, "Side of the square terrain, metres")
      ->check(real_between(8.0, 200.0))
      ->capture_default_str();
  app->add_option("--x", o->pose.x,
                  "Rover position east, metres (at least 2 m inside the terrain's edge)")
      ->check(real_between(-kMaxPositionM, kMaxPositionM))
      ->capture_default_str();
  app->add_option("--y", o->pose.y,
                  "Rover position north, metres (at least 2 m inside the terrain's edge)")
      ->check(real_between(-kMaxPositionM, kMaxPositionM))
      ->capture_default_str();
  app->add_option("--heading", o->pose.heading_deg,
                  "Rover heading, degrees counter-clockwise from east")
      ->check(real_between(-360.0, 360.0))
      ->capture_default_str();
  app->add_option("--noise", o->noise, "Sensor noise standard deviation, grey levels")
      ->check(real_between(0.0, 64.0))
      ->capture_default_str();
  app->add_option("--misalign-pan", o->pan, "Right camera pan misalignment, arc seconds")
      ->check(real_between(-kMaxMisalignmentArcsec, kMaxMisalignmentArcsec));
  app->add_option("--misalign-tilt", o->tilt, "Right camera tilt misalignment, arc seconds")
      ->check(real_between(-kMaxMisalignmentArcsec, kMaxMisalignmentArcsec));
  app->add_option("--misalign-roll", o->roll, "Right camera roll misalignment, arc seconds")
      ->check(real_between(-kMaxMisalignmentArcsec, kMaxMisalignmentArcsec));
  app->add_option("--rig", o->rig_file,
                  "Rig TOML file (docs/formats.md); --size and "
                  "--misalign-* override its values");
  app->add_flag("--json", o->json, "Print a machine-readable summary on stdout");
  return {app, [o] { return run_world(*o); }};
}

} // namespace marsokhod::apps
