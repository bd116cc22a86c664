// The inputs of a navigation cycle on a pair: images, rig, calibration and attitude, read with
// the errors a user can act on.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace marsokhod::apps {

/// An 8-bit grey image; CommandError naming the file when it cannot be read.
imaging::Image<std::uint8_t> read_grey(const std::filesystem::path& path);

/// The rig file's rig, which must have the images' size, or without one the paper's rig at
/// that size; CommandError naming the file (or `left` for the images) otherwise.
imaging::StereoRig rig_for(const std::optional<std::filesystem::path>& rig_file,
                           const std::filesystem::path& left, int width, int height);

/// The right image with the calibrated vertical parallax removed, or unchanged without a
/// calibration file.
imaging::Image<std::uint8_t> aligned_right(const std::optional<std::filesystem::path>& calibration,
                                           imaging::Image<std::uint8_t> right);

/// The attitude the world placed the rover in, as its scene.json records it.
imaging::Attitude scene_attitude(const std::filesystem::path& path);

} // namespace marsokhod::apps
