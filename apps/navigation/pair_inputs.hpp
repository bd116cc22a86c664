// The inputs of a navigation cycle on a pair: images, rig, calibration and attitude, read with
// the errors a user can act on.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace CLI {
class App;
} // namespace CLI

namespace marsokhod::apps {

/// The options that describe a pair beside its two images, shared by every command that runs a
/// cycle on one: its rig, the rover's attitude (or the scene file that records it) and the
/// vertical parallax calibration.
struct PairOptions {
  std::optional<std::filesystem::path> rig_file;
  std::optional<std::filesystem::path> scene_file;
  std::optional<std::filesystem::path> calibration_file;
  double pitch_deg = 0.0;
  double roll_deg = 0.0;
};

/// Adds --rig, --pitch, --roll, --scene and --calibration to a command.
void add_pair_options(CLI::App& app, PairOptions& options);

/// The rover's attitude: from the scene file when given, else --pitch and --roll.
imaging::Attitude pair_attitude(const PairOptions& options);

/// An 8-bit grey image; imaging::ImageError naming the file when it cannot be read.
imaging::Image<std::uint8_t> read_grey(const std::filesystem::path& path);

/// The rig file's rig, which must have the images' size, or without one the paper's rig at
/// that size. A file that cannot be read is an io::InputError, a wrong one an
/// imaging::RigFileError, each naming the file; a rig of another size is a CommandError naming
/// the file (or `left` for the images).
imaging::StereoRig rig_for(const std::optional<std::filesystem::path>& rig_file,
                           const std::filesystem::path& left, int width, int height);

/// The right image with the calibrated vertical parallax removed, or unchanged without a
/// calibration file.
imaging::Image<std::uint8_t> aligned_right(const std::optional<std::filesystem::path>& calibration,
                                           imaging::Image<std::uint8_t> right);

/// The attitude the world placed the rover in, as its scene.json records it.
imaging::Attitude scene_attitude(const std::filesystem::path& path);

} // namespace marsokhod::apps
