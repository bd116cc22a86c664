// Reading back what a scene.json written by the world records (format in docs/formats.md).
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"

#include <filesystem>
#include <stdexcept>

namespace marsokhod::world {

/// A scene file that cannot be opened or lacks what is asked of it; the message names the file.
class SceneFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The largest pitch or roll a scene file may record, degrees: the attitude `marsokhod nav
/// --pitch/--roll` accept (the inclinometers' range).
inline constexpr double kMaxSceneAttitudeDeg = 45.0;

/// The attitude the world placed the rover in (placement.attitude of scene.json), read through
/// the bounded JSON reader (regular files of at most 16 MiB). Throws SceneFileError naming the
/// file, and the key where one is to blame: a file that cannot be read or is no JSON, a missing
/// key, a value that is not a number or not within -45..45 deg.
imaging::Attitude read_scene_attitude(const std::filesystem::path& path);

} // namespace marsokhod::world
