// `marsokhod nav LEFT RIGHT --out DIR`: one navigation cycle on a stereo pair (docs/navigation.md).

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "navigation/nav_outputs.hpp"
#include "navigation/pair_inputs.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/image/output_folder.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/scene/scene_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

struct NavCli {
  fs::path left;
  fs::path right;
  fs::path out;
  PairOptions pair;
  std::optional<fs::path> disparity_file;
  double heading_deg = 0.0;
  double max_step_m = nav::ZoneOptions{}.max_step_m;
  bool json = false;
};

// +inf is the Middlebury "unknown"; anything else that is not a finite disparity >= 0 is an
// error in the file, not something to guess around.
imaging::Image<float> read_disparity(const fs::path& path, int width, int height) {
  const imaging::Image<float> disparity = imaging::read_pfm(path);
  if (disparity.width() != width || disparity.height() != height)
    throw CommandError(fmt::format("{}: the disparity map is {}x{} but the images are {}x{}",
                                   path.string(), disparity.width(), disparity.height(), width,
                                   height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float d = disparity(x, y);
      if (std::isnan(d) || d == -std::numeric_limits<float>::infinity() || d < 0.0F)
        throw CommandError(fmt::format("{}: pixel ({}, {}) holds {}; disparities must be >= 0, "
                                       "or +inf where unknown",
                                       path.string(), x, y, d));
    }
  return disparity;
}

void print_summary(const nav::NavigationResult& result, const fs::path& out, double seconds) {
  if (result.found()) {
    fmt::print("path found: start {:.2f} m, fracture points [{:.2f}] m, target {:.2f} m\n",
               result.drive.start_m, fmt::join(result.drive.fracture_m, ", "),
               result.drive.target_m);
    for (const nav::DriveCommand& c : result.drive.commands)
      fmt::print("  turn {:+7.2f} deg, drive {:6.2f} m\n", c.turn_deg, c.distance_m);
  } else {
    fmt::print("no path: {}\n", result.reason());
  }
  fmt::print("zones: {} traversable, {} unknown, {} step, {} slope, {} margin pixels\n",
             result.zones.count(nav::Zone::traversable), result.zones.count(nav::Zone::unknown),
             result.zones.count(nav::Zone::step), result.zones.count(nav::Zone::slope),
             result.zones.count(nav::Zone::margin));
  fmt::print("wrote disparity, range, elevation, zones, path overlay and path.json to {} "
             "(navigation {:.1f} ms)\n",
             out.string(), 1000.0 * seconds);
}

int run_nav(const NavCli& cli) {
  const imaging::Image<std::uint8_t> left = read_grey(cli.left);
  imaging::Image<std::uint8_t> right = read_grey(cli.right);
  if (left.width() != right.width() || left.height() != right.height())
    throw CommandError(fmt::format("{} is {}x{} but {} is {}x{}; a stereo pair has one size",
                                   cli.left.string(), left.width(), left.height(),
                                   cli.right.string(), right.width(), right.height()));
  const imaging::StereoRig rig = rig_for(cli.pair.rig_file, cli.left, left.width(), left.height());
  right = aligned_right(cli.pair.calibration_file, std::move(right));
  nav::NavigationOptions options;
  options.attitude = pair_attitude(cli.pair);
  options.planner.heading_deg = cli.heading_deg;
  options.zones.max_step_m = cli.max_step_m;
  std::optional<imaging::Image<float>> given;
  if (cli.disparity_file)
    given = read_disparity(*cli.disparity_file, left.width(), left.height());
  imaging::prepare_output_folder(cli.out);

  const auto start = std::chrono::steady_clock::now();
  nav::NavigationResult result;
  try {
    result = given ? nav::navigate_disparity(*given, {}, rig, options)
                   : nav::navigate(left, right, rig, options);
  } catch (const std::invalid_argument& error) {
    throw CommandError(fmt::format("{}: {}", cli.left.string(), error.what()));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const imaging::Image<float>& disparity = given ? *given : result.stereo.disparity;
  const auto written = write_navigation_outputs(cli.out, left, disparity, result);
  if (!cli.json) {
    print_summary(result, cli.out, seconds);
    return kSuccess;
  }
  nlohmann::ordered_json summary = path_json(result);
  summary.erase("pixel_path");
  nlohmann::ordered_json files = nlohmann::ordered_json::object();
  for (const auto& [key, path] : written)
    files[key] = path.string();
  summary["outputs"] = files;
  summary["seconds"] = seconds;
  fmt::print("{}\n", summary.dump(2));
  return kSuccess;
}

} // namespace

Command make_nav_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "nav", "Navigate on one stereo pair: disparity, range, elevation, prohibited zones, the "
             "safest path and drive commands, written into a folder.");
  auto cli = std::make_shared<NavCli>();
  app->add_option("LEFT", cli->left, "Left (reference) image: PGM, PPM or PNG")->required();
  app->add_option("RIGHT", cli->right, "Right image of the same size")->required();
  app->add_option("--out", cli->out, "Output folder (created if missing)")->required();
  add_pair_options(*app, cli->pair);
  app->add_option("--heading", cli->heading_deg,
                  "Mission heading relative to the rover's, deg, counter-clockwise +")
      ->check(real_between(-180.0, 180.0))
      ->capture_default_str();
  app->add_option("--max-step", cli->max_step_m, "Largest step the rover climbs, m")
      ->check(real_between(0.01, 5.0))
      ->capture_default_str();
  app->add_option("--disparity", cli->disparity_file,
                  "Use this disparity map (PFM, +inf unknown) instead of matching the pair");
  app->add_flag("--json", cli->json, "Print a machine-readable summary on stdout");
  return {app, [cli] { return run_nav(*cli); }};
}

} // namespace marsokhod::apps
