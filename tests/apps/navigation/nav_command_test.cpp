// `marsokhod nav`: its outputs on a rendered scene, and its exit codes and messages for bad inputs.
#include "support/run_marsokhod.hpp"

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using marsokhod::imaging::Image;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

fs::path nav_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-nav-tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A rendered 128 px scene of a small site, made once per test process. ctest runs each test in
// a process of its own, in parallel, so each one renders into a folder named for its test.
const fs::path& scene() {
  static const fs::path dir = [] {
    const fs::path folder = nav_folder(
        std::string("scene-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    const auto result =
        run_marsokhod("world --terrain-size 16 --size 128 --seed 2 --out " + quoted(folder));
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return folder;
  }();
  return dir;
}

std::string nav_args(const fs::path& out) {
  return "nav " + quoted(scene() / "left.pgm") + " " + quoted(scene() / "right.pgm") + " --out " +
         quoted(out);
}

TEST(NavCommand, WritesEveryOutputAndThePathDocument) {
  const fs::path out = nav_folder("outputs");
  const auto result = run_marsokhod(nav_args(out) + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* name : {"disparity.pfm", "disparity.png", "range.pfm", "elevation.pfm",
                           "elevation.png", "zones.png", "path_overlay.png", "path.json"})
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  const auto path = nlohmann::json::parse(slurp(out / "path.json"));
  ASSERT_TRUE(path.contains("found"));
  if (path["found"]) {
    for (const char* key :
         {"pixel_path", "ground_polyline", "start_m", "fracture_m", "target_m", "commands"})
      EXPECT_TRUE(path.contains(key)) << key;
    EXPECT_GE(path["target_m"].get<double>(), 10.0);
    EXPECT_LE(path["target_m"].get<double>(), 12.0);
    EXPECT_EQ(path["ground_polyline"].size(), path["fracture_m"].size() + 2);
  } else {
    EXPECT_FALSE(path["reason"].get<std::string>().empty());
  }
  const auto summary = nlohmann::json::parse(result.out);
  EXPECT_EQ(summary["found"], path["found"]);
  EXPECT_EQ(summary["outputs"]["zones"], (out / "zones.png").string());
  const auto zones = marsokhod::imaging::read_gray8(out / "zones.png");
  EXPECT_EQ(zones.width(), 128);
  const auto overlay = marsokhod::imaging::read_image(out / "path_overlay.png");
  EXPECT_EQ(std::get<Image<std::uint8_t>>(overlay).channels(), 3);
}

TEST(NavCommand, SameInputsGiveByteIdenticalFiles) {
  const fs::path first = nav_folder("repeat-1");
  const fs::path second = nav_folder("repeat-2");
  ASSERT_EQ(run_marsokhod(nav_args(first)).exit_code, 0);
  ASSERT_EQ(run_marsokhod(nav_args(second)).exit_code, 0);
  for (const char* name : {"disparity.pfm", "elevation.pfm", "zones.png", "path.json"})
    EXPECT_EQ(slurp(first / name), slurp(second / name)) << name;
}

TEST(NavCommand, GroundTruthDisparityOfTheSceneGivesAPath) {
  const fs::path out = nav_folder("truth");
  const auto result = run_marsokhod(nav_args(out) + " --disparity " +
                                    quoted(scene() / "gt_disparity.pfm") + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = nlohmann::json::parse(result.out);
  EXPECT_TRUE(summary.contains("found"));
}

void write_grey(const fs::path& path, int width, int height, std::uint8_t grey) {
  marsokhod::imaging::write_image(path, Image<std::uint8_t>(width, height, 1, grey).view());
}

TEST(NavCommand, ImagesOfDifferentSizesAreAnErrorNamingBoth) {
  const fs::path dir = nav_folder("sizes");
  write_grey(dir / "l.pgm", 64, 64, 100);
  write_grey(dir / "r.pgm", 64, 60, 100);
  const auto result = run_marsokhod("nav " + quoted(dir / "l.pgm") + " " + quoted(dir / "r.pgm") +
                                    " --out " + quoted(dir / "out"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("l.pgm is 64x64"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("r.pgm is 64x60"), std::string::npos) << result.err;
}

TEST(NavCommand, ImagesTooSmallForThePyramidAreAnError) {
  const fs::path dir = nav_folder("tiny");
  write_grey(dir / "l.pgm", 6, 6, 100);
  const auto result = run_marsokhod("nav " + quoted(dir / "l.pgm") + " " + quoted(dir / "l.pgm") +
                                    " --out " + quoted(dir / "out"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("l.pgm"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("6x6 images are too small"), std::string::npos) << result.err;
}

TEST(NavCommand, AllBlackAndAllWhitePairsGiveNoPathWithAReason) {
  for (const std::uint8_t grey : {std::uint8_t{0}, std::uint8_t{255}}) {
    const fs::path dir = nav_folder("uniform-" + std::to_string(grey));
    write_grey(dir / "flat.pgm", 64, 64, grey);
    const auto result = run_marsokhod("nav " + quoted(dir / "flat.pgm") + " " +
                                      quoted(dir / "flat.pgm") + " --out " + quoted(dir / "out"));
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const auto path = nlohmann::json::parse(slurp(dir / "out" / "path.json"));
    EXPECT_FALSE(path["found"].get<bool>());
    EXPECT_FALSE(path["reason"].get<std::string>().empty());
    EXPECT_NE(result.out.find("no path"), std::string::npos) << result.out;
  }
}

TEST(NavCommand, NanInADisparityFileIsAnErrorNamingTheFileAndPixel) {
  const fs::path dir = nav_folder("nan");
  Image<float> disparity(128, 128, 1, 20.0F);
  disparity(5, 7) = std::numeric_limits<float>::quiet_NaN();
  marsokhod::imaging::write_image(dir / "d.pfm", disparity.view());
  const auto result =
      run_marsokhod(nav_args(dir / "out") + " --disparity " + quoted(dir / "d.pfm"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("d.pfm: pixel (5, 7)"), std::string::npos) << result.err;
}

TEST(NavCommand, InfiniteDisparitiesAreUnknownGroundAndGiveNoPath) {
  const fs::path dir = nav_folder("inf");
  const Image<float> unknown(128, 128, 1, std::numeric_limits<float>::infinity());
  marsokhod::imaging::write_image(dir / "d.pfm", unknown.view());
  const auto result =
      run_marsokhod(nav_args(dir / "out") + " --disparity " + quoted(dir / "d.pfm") + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = nlohmann::json::parse(result.out);
  EXPECT_FALSE(summary["found"].get<bool>());
  EXPECT_FALSE(summary["reason"].get<std::string>().empty());
}

TEST(NavCommand, AFloatImageAsLeftIsAnErrorNamingTheFile) {
  const fs::path dir = nav_folder("float-left");
  const Image<float> pixels(64, 64, 1, std::numeric_limits<float>::infinity());
  marsokhod::imaging::write_image(dir / "left.pfm", pixels.view());
  const auto result = run_marsokhod("nav " + quoted(dir / "left.pfm") + " " +
                                    quoted(dir / "left.pfm") + " --out " + quoted(dir / "out"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("left.pfm"), std::string::npos) << result.err;
}

TEST(NavCommand, ARigWithANegativeBaselineIsAnError) {
  const fs::path dir = nav_folder("rig");
  std::ofstream(dir / "bad.toml") << "[rig]\nbaseline_m = -0.5\nwidth_px = 128\nheight_px = 128\n";
  const auto result = run_marsokhod(nav_args(dir / "out") + " --rig " + quoted(dir / "bad.toml"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("bad.toml"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("baseline"), std::string::npos) << result.err;
}

TEST(NavCommand, ARigOfAnotherSizeIsAnError) {
  const fs::path dir = nav_folder("rig-size");
  std::ofstream(dir / "rig.toml") << "[rig]\nwidth_px = 256\nheight_px = 256\n";
  const auto result = run_marsokhod(nav_args(dir / "out") + " --rig " + quoted(dir / "rig.toml"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("the rig is 256x256 but the images are 128x128"), std::string::npos)
      << result.err;
}

TEST(NavCommand, TheSceneFilesAttitudeIsUsedAndBadSceneFilesAreErrorsNamingThem) {
  const fs::path out = nav_folder("scene-attitude");
  const auto result = run_marsokhod(nav_args(out / "out") + " --scene " +
                                    quoted(scene() / "scene.json") + " --json");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const fs::path missing = out / "nowhere.json";
  const auto none = run_marsokhod(nav_args(out / "out") + " --scene " + quoted(missing));
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.err.find(missing.string() + ": cannot open the scene file"), std::string::npos)
      << none.err;
  std::ofstream(out / "other.json") << R"({"placement": {}})";
  const auto other =
      run_marsokhod(nav_args(out / "out") + " --scene " + quoted(out / "other.json"));
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_NE(other.err.find((out / "other.json").string() +
                           ": not a scene file with placement.attitude: "),
            std::string::npos)
      << other.err;
}

} // namespace
