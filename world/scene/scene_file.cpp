// The scene.json reader: the rover's attitude, with errors naming the file.
#include "marsokhod/world/scene/scene_file.hpp"

#include "scene/scene_keys.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace marsokhod::world {

imaging::Attitude read_scene_attitude(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneFileError(fmt::format("{}: cannot open the scene file", path.string()));
  try {
    const nlohmann::json scene = nlohmann::json::parse(in);
    const nlohmann::json& attitude = scene.at(scene_keys::kPlacement).at(scene_keys::kAttitude);
    return {attitude.at(scene_keys::kPitch).get<double>(),
            attitude.at(scene_keys::kRoll).get<double>()};
  } catch (const nlohmann::json::exception& error) {
    throw SceneFileError(fmt::format("{}: not a scene file with {}.{}: {}", path.string(),
                                     scene_keys::kPlacement, scene_keys::kAttitude, error.what()));
  }
}

} // namespace marsokhod::world
