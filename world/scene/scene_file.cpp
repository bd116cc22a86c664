// The scene.json reader: the rover's attitude, checked, with errors naming the file and key.
#include "marsokhod/world/scene/scene_file.hpp"

#include "scene/scene_keys.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/json_file.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace marsokhod::world {
namespace {

std::string_view json_type_name(const nlohmann::json& node) {
  switch (node.type()) {
  case nlohmann::json::value_t::object:
    return "an object";
  case nlohmann::json::value_t::array:
    return "an array";
  case nlohmann::json::value_t::string:
    return "a string";
  case nlohmann::json::value_t::boolean:
    return "a boolean";
  case nlohmann::json::value_t::null:
    return "null";
  default:
    return "a number";
  }
}

/// A parsed scene.json being taken apart; every problem names the file and the key.
class SceneReader {
public:
  explicit SceneReader(const std::filesystem::path& path) : path_(path) {}

  imaging::Attitude attitude() const {
    nlohmann::json document;
    try {
      document = io::parse_json_file(path_, "scene file");
    } catch (const io::InputError& error) {
      throw SceneFileError(error.what());
    }
    require_object(document, "the document");
    const std::string placement_name(scene_keys::kPlacement);
    const nlohmann::json& placement = member(document, scene_keys::kPlacement, placement_name);
    require_object(placement, "key '" + placement_name + "'");
    const std::string attitude_name = placement_name + "." + std::string(scene_keys::kAttitude);
    const nlohmann::json& attitude = member(placement, scene_keys::kAttitude, attitude_name);
    require_object(attitude, "key '" + attitude_name + "'");
    return {angle(attitude, attitude_name, scene_keys::kPitch),
            angle(attitude, attitude_name, scene_keys::kRoll)};
  }

private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw SceneFileError(fmt::format("{}: {}", path_.string(), problem));
  }

  void require_object(const nlohmann::json& node, const std::string& what) const {
    if (!node.is_object())
      fail(fmt::format("not a scene file with placement.attitude: {} must be an object (got {})",
                       what, json_type_name(node)));
  }

  // `node` is an object; `name` is the key's full dotted name for messages.
  const nlohmann::json& member(const nlohmann::json& node, std::string_view key,
                               const std::string& name) const {
    const auto found = node.find(std::string(key));
    if (found == node.end())
      fail(fmt::format("not a scene file with placement.attitude: it has no key '{}'", name));
    return *found;
  }

  double angle(const nlohmann::json& attitude, const std::string& table,
               std::string_view key) const {
    const std::string name = table + "." + std::string(key);
    const nlohmann::json& node = member(attitude, key, name);
    if (!node.is_number())
      fail(fmt::format("key '{}' must be a number (got {})", name, json_type_name(node)));
    const double value = node.get<double>();
    if (!std::isfinite(value) || value < -kMaxSceneAttitudeDeg || value > kMaxSceneAttitudeDeg)
      fail(fmt::format("key '{}' = {} must be {} deg (the attitude nav --pitch and --roll accept)",
                       name, value, io::range_text(-kMaxSceneAttitudeDeg, kMaxSceneAttitudeDeg)));
    return value;
  }

  std::filesystem::path path_;
};

} // namespace

imaging::Attitude read_scene_attitude(const std::filesystem::path& path) {
  return SceneReader(path).attitude();
}

} // namespace marsokhod::world
