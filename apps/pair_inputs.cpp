// Reading a cycle's pair, rig, calibration and attitude, each failure naming its file.

#include "pair_inputs.hpp"

#include "command.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/world/scene/scene_file.hpp"

#include <fmt/format.h>

#include <exception>

namespace marsokhod::apps {

namespace fs = std::filesystem;

imaging::Image<std::uint8_t> read_grey(const fs::path& path) {
  try {
    return imaging::read_gray8(path);
  } catch (const imaging::ImageError& error) {
    throw CommandError(error.what());
  }
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
  try {
    imaging::StereoRig rig = imaging::StereoRig::load(*rig_file);
    if (rig.width() != width || rig.height() != height)
      throw CommandError(fmt::format("{}: the rig is {}x{} but the images are {}x{}",
                                     rig_file->string(), rig.width(), rig.height(), width, height));
    return rig;
  } catch (const imaging::RigError& error) {
    throw CommandError(error.what());
  }
}

imaging::Image<std::uint8_t> aligned_right(const std::optional<fs::path>& calibration,
                                           imaging::Image<std::uint8_t> right) {
  if (!calibration)
    return right;
  try {
    const nav::VerticalParallaxMap map = nav::load_vertical_parallax(*calibration);
    nav::check_map_size(map, right.width(), right.height(), calibration->string());
    return nav::remove_vertical_parallax(right, map);
  } catch (const nav::CalibrationError& error) {
    throw CommandError(error.what());
  }
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

} // namespace marsokhod::apps
