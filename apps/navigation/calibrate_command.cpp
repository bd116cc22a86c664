// `marsokhod calibrate LEFT RIGHT --out FILE`: the vertical parallax map of a calibration pair
// (docs/navigation.md, "Vertical parallax calibration").

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "navigation/pair_inputs.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/nav/calibration/vertical_parallax_calibration.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

struct CalibrateCli {
  fs::path left;
  fs::path right;
  fs::path out;
  std::optional<int> max_disparity;
  int max_shift = nav::CalibrationOptions{}.max_shift;
  bool json = false;
};

// The rover's own search range at this image size unless the user gives one.
int default_max_disparity(int width, int height) {
  imaging::RigParameters parameters;
  parameters.width_px = width;
  parameters.height_px = height;
  try {
    return nav::rover_max_disparity(imaging::StereoRig(parameters), {});
  } catch (const imaging::RigError&) {
    return width / 4;
  }
}

nlohmann::ordered_json summary_json(const nav::CalibrationResult& result, const fs::path& out) {
  const nav::VerticalParallaxMap& map = result.map;
  const auto& c = map.coefficients;
  const double right = map.width - 1;
  const double bottom = map.height - 1;
  nlohmann::ordered_json json;
  json["output"] = out.string();
  json["width"] = map.width;
  json["height"] = map.height;
  json["coefficients"] = {{"c0", c[0]},  {"cx", c[1]},  {"cy", c[2]},
                          {"cxx", c[3]}, {"cxy", c[4]}, {"cyy", c[5]}};
  json["shift_centre_rows"] = map.shift_at(0.5 * right, 0.5 * bottom);
  json["shift_corners_rows"] = {map.shift_at(0, 0), map.shift_at(right, 0), map.shift_at(0, bottom),
                                map.shift_at(right, bottom)};
  json["largest_shift_rows"] = map.largest_shift();
  json["blocks_searched"] = result.blocks_searched;
  json["blocks_matched"] = result.samples.size();
  json["inliers"] = result.inliers;
  json["rms_residual_rows"] = result.rms_residual;
  return json;
}

int run_calibrate(const CalibrateCli& cli) {
  const imaging::Image<std::uint8_t> left = read_grey(cli.left);
  const imaging::Image<std::uint8_t> right = read_grey(cli.right);
  nav::CalibrationOptions options;
  options.max_disparity =
      cli.max_disparity.value_or(default_max_disparity(left.width(), left.height()));
  options.max_shift = cli.max_shift;
  nav::CalibrationResult result;
  try {
    result = nav::calibrate_vertical_parallax(left, right, options);
  } catch (const nav::CalibrationError& error) {
    throw CommandError(fmt::format("{}: {}", cli.left.string(), error.what()));
  }
  const nlohmann::ordered_json summary = summary_json(result, cli.out);
  io::write_file_atomically(
      cli.out, nav::vertical_parallax_to_toml(
                   result.map, fmt::format("fitted to {} and {}: {} of {} blocks matched, residual "
                                           "{:.3f} rows rms",
                                           cli.left.filename().string(),
                                           cli.right.filename().string(), result.samples.size(),
                                           result.blocks_searched, result.rms_residual)));
  if (cli.json) {
    fmt::print("{}\n", summary.dump(2));
    return kSuccess;
  }
  const nav::VerticalParallaxMap& map = result.map;
  fmt::print("vertical parallax: {:+.3f} rows at the centre, up to {:.3f} rows over the image\n",
             map.shift_at(0.5 * (map.width - 1), 0.5 * (map.height - 1)), map.largest_shift());
  fmt::print("{} of {} blocks matched; last pass {} inliers, residual {:.3f} rows rms; wrote {}\n",
             result.samples.size(), result.blocks_searched, result.inliers, result.rms_residual,
             cli.out.string());
  return kSuccess;
}

} // namespace

Command make_calibrate_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "calibrate", "Measure the vertical parallax of a calibration pair (searching both "
                   "directions) and save it for `marsokhod nav --calibration`.");
  auto cli = std::make_shared<CalibrateCli>();
  app->add_option("LEFT", cli->left, "Left (reference) image: PGM, PPM or PNG")->required();
  app->add_option("RIGHT", cli->right, "Right image of the same size")->required();
  app->add_option("--out", cli->out, "Calibration file to write (TOML)")->required();
  app->add_option("--max-disparity", cli->max_disparity,
                  "Horizontal search, px (default: the rover's range at the images' size)")
      ->transform(integer_between(2, 1024));
  app->add_option("--max-shift", cli->max_shift, "Vertical search either way, rows")
      ->transform(integer_between(2, 32))
      ->capture_default_str();
  app->add_flag("--json", cli->json, "Print a machine-readable summary on stdout");
  return {app, [cli] { return run_calibrate(*cli); }};
}

} // namespace marsokhod::apps
