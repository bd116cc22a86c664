// scene.json written by the world and read back: the rover's attitude, and errors naming the file.
#include "marsokhod/world/scene/scene.hpp"
#include "marsokhod/world/scene/scene_file.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace marsokhod::world {
namespace {

namespace fs = std::filesystem;

class SceneFile : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("marsokhod-scene-file-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& text) const {
    const fs::path file = dir_ / "scene.json";
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

  // The message read_scene_attitude throws for `file`.
  static std::string error_of(const fs::path& file) {
    try {
      read_scene_attitude(file);
    } catch (const SceneFileError& error) {
      return error.what();
    }
    ADD_FAILURE() << "no SceneFileError for " << file;
    return {};
  }

  fs::path dir_;
};

TEST_F(SceneFile, TheAttitudeTheWriterRecordsIsReadBack) {
  SceneDescription scene;
  scene.placement.attitude = {3.5, -1.25};
  const fs::path file = write(scene_to_json(scene).dump(2) + "\n");
  const imaging::Attitude attitude = read_scene_attitude(file);
  EXPECT_DOUBLE_EQ(attitude.pitch_deg, 3.5);
  EXPECT_DOUBLE_EQ(attitude.roll_deg, -1.25);
}

TEST_F(SceneFile, TheWriterKeepsTheDocumentedKeys) {
  SceneDescription scene;
  const nlohmann::json json = scene_to_json(scene);
  EXPECT_EQ(json.at("format"), "marsokhod-scene");
  EXPECT_EQ(json.at("version"), 1);
  for (const char* key :
       {"terrain", "lighting", "rig", "placement", "render", "ground_truth", "outputs"})
    EXPECT_TRUE(json.contains(key)) << key;
  for (const char* key : {"pose", "ground_z_m", "attitude", "level_to_world"})
    EXPECT_TRUE(json.at("placement").contains(key)) << key;
  EXPECT_TRUE(json.at("placement").at("attitude").contains("pitch_deg"));
  EXPECT_TRUE(json.at("placement").at("attitude").contains("roll_deg"));
}

TEST_F(SceneFile, AMissingFileCannotBeOpened) {
  const fs::path file = dir_ / "nowhere.json";
  EXPECT_EQ(error_of(file), file.string() + ": cannot open the scene file");
}

TEST_F(SceneFile, ADocumentWithoutTheAttitudeIsNotASceneFile) {
  const fs::path file = write(R"({"placement": {"pose": {}}})");
  const std::string message = error_of(file);
  EXPECT_EQ(message.rfind(file.string() + ": not a scene file with placement.attitude: ", 0), 0U)
      << message;
  EXPECT_NE(message.find("'attitude'"), std::string::npos) << message;
}

TEST_F(SceneFile, TextThatIsNoJsonAndAStringPitchAreRefused) {
  EXPECT_NE(error_of(write("not json")).find("not a scene file"), std::string::npos);
  const std::string message =
      error_of(write(R"({"placement": {"attitude": {"pitch_deg": "up", "roll_deg": 0}}})"));
  EXPECT_NE(message.find("not a scene file with placement.attitude"), std::string::npos) << message;
}

} // namespace
} // namespace marsokhod::world
