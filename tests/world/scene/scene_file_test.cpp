// scene.json written by the world and read back: the rover's attitude, and errors naming the file.
#include "marsokhod/world/scene/scene.hpp"
#include "marsokhod/world/scene/scene_file.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
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
  const std::string message = error_of(file);
  EXPECT_EQ(message.rfind(file.string() + ": cannot open the scene file", 0), 0U) << message;
}

// Read through the bounded reader: a device or a FIFO is refused at once, never read.
TEST_F(SceneFile, ADeviceOrAFifoIsRefusedWithoutBeingRead) {
  EXPECT_EQ(error_of("/dev/zero").rfind("/dev/zero: is a device", 0), 0U) << error_of("/dev/zero");
  const fs::path fifo = dir_ / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of(fifo).rfind(fifo.string() + ": is a FIFO", 0), 0U) << error_of(fifo);
}

TEST_F(SceneFile, ADocumentWithoutTheAttitudeNamesTheMissingKey) {
  const fs::path file = write(R"({"placement": {"pose": {}}})");
  EXPECT_EQ(error_of(file),
            file.string() +
                ": not a scene file with placement.attitude: it has no key 'placement.attitude'");
  const fs::path no_roll = write(R"({"placement": {"attitude": {"pitch_deg": 1}}})");
  EXPECT_EQ(error_of(no_roll), no_roll.string() + ": not a scene file with placement.attitude: it "
                                                  "has no key 'placement.attitude.roll_deg'");
  const fs::path array = write("[1, 2]");
  EXPECT_EQ(error_of(array), array.string() + ": not a scene file with placement.attitude: the "
                                              "document must be an object (got an array)");
  const fs::path flat = write(R"({"placement": {"attitude": 3}})");
  EXPECT_EQ(error_of(flat),
            flat.string() +
                ": not a scene file with placement.attitude: key 'placement.attitude' must be "
                "an object (got a number)");
}

TEST_F(SceneFile, TextThatIsNoJsonAndAStringPitchAreRefused) {
  EXPECT_NE(error_of(write("not json")).find("not a scene file"), std::string::npos);
  const fs::path file = write(R"({"placement": {"attitude": {"pitch_deg": "up", "roll_deg": 0}}})");
  EXPECT_EQ(error_of(file),
            file.string() + ": key 'placement.attitude.pitch_deg' must be a number (got a string)");
}

// The issue's example: pitch_deg = 1e308 was accepted as the rover's attitude.
TEST_F(SceneFile, AnAttitudeOutsideWhatNavAcceptsIsRefusedNamingTheKey) {
  const fs::path file =
      write(R"({"placement": {"attitude": {"pitch_deg": 1e308, "roll_deg": 0}}})");
  EXPECT_EQ(error_of(file), file.string() +
                                ": key 'placement.attitude.pitch_deg' = 1e+308 must be between "
                                "-45 and 45 deg (the attitude nav --pitch and --roll accept)");
}

// The general rule, for both keys: -45..45 (nav --pitch/--roll), the ends included.
TEST_F(SceneFile, PitchAndRollAreAcceptedExactlyWithinPlusMinus45Degrees) {
  for (const char* key : {"pitch_deg", "roll_deg"}) {
    const std::string other = std::string(key) == "pitch_deg" ? "roll_deg" : "pitch_deg";
    for (const char* value : {"-45", "45", "-44.999999", "0"}) {
      const fs::path file = write(fmt::format(
          R"({{"placement": {{"attitude": {{"{}": {}, "{}": 1}}}}}})", key, value, other));
      EXPECT_NO_THROW(read_scene_attitude(file)) << key << " = " << value;
    }
    for (const char* value : {"-45.000001", "45.000001", "-1e308", "true", "null"}) {
      const fs::path file = write(fmt::format(
          R"({{"placement": {{"attitude": {{"{}": {}, "{}": 1}}}}}})", key, value, other));
      const std::string message = error_of(file);
      EXPECT_NE(message.find(std::string("placement.attitude.") + key), std::string::npos)
          << value << ": " << message;
    }
  }
  // A number beyond the double range does not even parse; the message still names the file.
  const fs::path huge =
      write(R"({"placement": {"attitude": {"pitch_deg": 1e999, "roll_deg": 0}}})");
  EXPECT_EQ(error_of(huge).rfind(huge.string() + ": not a scene file: ", 0), 0U) << error_of(huge);
  const fs::path exact =
      write(R"({"placement": {"attitude": {"pitch_deg": -45, "roll_deg": 45}}})");
  EXPECT_EQ(read_scene_attitude(exact).pitch_deg, -45.0);
  EXPECT_EQ(read_scene_attitude(exact).roll_deg, 45.0);
}

} // namespace
} // namespace marsokhod::world
