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

/// The attitude the world placed the rover in (placement.attitude of scene.json). Throws
/// SceneFileError "<path>: cannot open the scene file" or "<path>: not a scene file with
/// placement.attitude: <what the JSON parser said>".
imaging::Attitude read_scene_attitude(const std::filesystem::path& path);

} // namespace marsokhod::world
