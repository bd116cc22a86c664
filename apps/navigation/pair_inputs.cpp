// Reading a cycle's pair, rig, calibration and attitude, each failure naming its file.

#include "navigation/pair_inputs.hpp"

#include "cli/command.hpp"
#include "cli/option_checks.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/world/scene/scene_file.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>

namespace marsokhod::apps {

namespace fs = std::filesystem;

imaging::Image<std::uint8_t> read_grey(const fs::path& path) {
  return imaging::read_gray8(path);
}

imaging::StereoRig rig_for(const std::optional<fs::path>& rig_file, const fs::path& left, int width,
                           int height) {
  if (!rig_file) {
    imaging::RigParameters parameters;
    parameters.width_px = width;
    parameters.height_px = height;
    try {
      return imaging::StereoRig(parameters);
    } catch (const imaging::RigError& error) {
      throw CommandError(fmt::format("{}: {}x{} images are too small or too large for the rig: {}",
                                     left.string(), width, height, error.what()));
    }
  }
  // A bad rig file is an io::InputError or an imaging::RigFileError, each naming the file.
  imaging::StereoRig rig = imaging::StereoRig::load(*rig_file);
  if (rig.width() != width || rig.height() != height)
    throw CommandError(fmt::format("{}: the rig is {}x{} but the images are {}x{}",
                                   rig_file->string(), rig.width(), rig.height(), width, height));
  return rig;
}

imaging::Image<std::uint8_t> aligned_right(const std::optional<fs::path>& calibration,
                                           imaging::Image<std::uint8_t> right) {
  if (!calibration)
    return right;
  const nav::VerticalParallaxMap map = nav::load_vertical_parallax(*calibration);
  nav::check_map_size(map, right.width(), right.height(), calibration->string());
  return nav::remove_vertical_parallax(right, map);
}

// Any other failure of the read (a stream error on a folder, say) is still this file's problem
// and is named so.
imaging::Attitude scene_attitude(const fs::path& path) {
  try {
    return world::read_scene_attitude(path);
  } catch (const world::SceneFileError& error) {
    throw CommandError(error.what());
  } catch (const std::exception& error) {
    throw CommandError(
        fmt::format("{}: cannot read the scene file: {}", path.string(), error.what()));
  }
}

void add_pair_options(CLI::App& app, PairOptions& options) {
  app.add_option("--rig", options.rig_file,
                 "Rig TOML file (docs/formats.md); default: the paper's rig at the images' size");
  CLI::Option* pitch = app.add_option("--pitch", options.pitch_deg,
                                      "Rover pitch from the inclinometer, deg, nose up +")
                           ->check(real_between(-45.0, 45.0))
                           ->capture_default_str();
  CLI::Option* roll =
      app.add_option("--roll", options.roll_deg, "Rover roll, deg, right side down +")
          ->check(real_between(-45.0, 45.0))
          ->capture_default_str();
  app.add_option("--scene", options.scene_file,
                 "Take pitch and roll from a scene.json written by `marsokhod world`")
      ->excludes(pitch)
      ->excludes(roll);
  app.add_option("--calibration", options.calibration_file,
                 "Remove this vertical parallax map (from `marsokhod calibrate`) from the right "
                 "image before matching");
}

imaging::Attitude pair_attitude(const PairOptions& options) {
  return options.scene_file ? scene_attitude(*options.scene_file)
                            : imaging::Attitude{options.pitch_deg, options.roll_deg};
}

} // namespace marsokhod::apps
