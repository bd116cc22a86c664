// Tests: `marsokhod world`, the files it writes, determinism and its errors.

#include "support/run_marsokhod.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::run_marsokhod;
using marsokhod::testing::slurp;

// A small terrain and small images keep each run short; the code paths are those of the
// default 48 m site.
const std::string kQuick = "--terrain-size 16 --size 64 ";

fs::path world_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-world-tests" / name;
  fs::remove_all(dir);
  return dir;
}

const std::vector<std::string> kFiles = {
    "left.pgm",         "right.pgm",        "gt_disparity.pfm", "gt_range.pfm", "gt_elevation.pfm",
    "gt_obstacles.pgm", "gt_valid.pgm",     "left.png",         "right.png",    "gt_disparity.png",
    "gt_range.png",     "gt_elevation.png", "gt_obstacles.png", "scene.json"};

TEST(WorldCommand, WritesEveryOutputAndAJsonSummary) {
  const fs::path dir = world_folder("outputs") / "nested";
  const auto result = run_marsokhod("world " + kQuick + "--seed 3 --light low-sun --json --out '" +
                                    dir.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const std::string& name : kFiles)
    EXPECT_TRUE(fs::is_regular_file(dir / name)) << name;
  const auto summary = nlohmann::json::parse(result.out);
  EXPECT_EQ(summary["seed"], 3);
  EXPECT_EQ(summary["size"], 64);
  EXPECT_EQ(summary["light"], "low-sun");
  EXPECT_EQ(summary["outputs"]["gt_disparity"], (dir / "gt_disparity.pfm").string());
  EXPECT_EQ(summary["outputs"]["left"], (dir / "left.pgm").string());
  EXPECT_TRUE(summary["attitude"].contains("pitch_deg"));
  const double valid = summary["valid_fraction"];
  EXPECT_GT(valid, 0.2);
  EXPECT_LE(valid, 1.0);

  const auto left = marsokhod::imaging::read_gray8(dir / "left.pgm");
  EXPECT_EQ(left.width(), 64);
  const auto disparity = marsokhod::imaging::read_pfm(dir / "gt_disparity.pfm");
  EXPECT_EQ(disparity.height(), 64);
  const auto scene = nlohmann::json::parse(slurp(dir / "scene.json"));
  EXPECT_EQ(scene["terrain"]["seed"], 3);
  EXPECT_EQ(scene["terrain"]["size_m"], 16.0);
  EXPECT_EQ(scene["rig"]["width_px"], 64);
  EXPECT_EQ(scene["lighting"]["preset"], "low-sun");
  EXPECT_EQ(scene["outputs"]["gt_valid"], "gt_valid.pgm");
}

TEST(WorldCommand, SameSeedGivesByteIdenticalFilesAndAnotherSeedDiffers) {
  const fs::path a = world_folder("same-a");
  const fs::path b = world_folder("same-b");
  const fs::path c = world_folder("other-seed");
  ASSERT_EQ(run_marsokhod("world " + kQuick + "--seed 9 --out '" + a.string() + "'").exit_code, 0);
  ASSERT_EQ(run_marsokhod("world " + kQuick + "--seed 9 --out '" + b.string() + "'").exit_code, 0);
  ASSERT_EQ(run_marsokhod("world " + kQuick + "--seed 10 --out '" + c.string() + "'").exit_code, 0);
  for (const std::string& name : kFiles) {
    const std::string first = slurp(a / name);
    ASSERT_FALSE(first.empty()) << name;
    EXPECT_EQ(first, slurp(b / name)) << name << " differs between two runs with one seed";
  }
  EXPECT_NE(slurp(a / "left.pgm"), slurp(c / "left.pgm"));
  EXPECT_NE(slurp(a / "gt_disparity.pfm"), slurp(c / "gt_disparity.pfm"));
}

TEST(WorldCommand, HumanSummaryNamesTheFolderAndTheFiles) {
  const fs::path dir = world_folder("human");
  const auto result = run_marsokhod("world " + kQuick + "--out '" + dir.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find(dir.string()), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("gt_disparity.pfm"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("timings"), std::string::npos) << result.out;
  EXPECT_NE(result.err.find("terrain"), std::string::npos) << result.err; // progress
}

TEST(WorldCommand, BadOptionValuesAreUsageErrors) {
  const fs::path dir = world_folder("bad");
  const std::string out = " --out '" + dir.string() + "'";
  for (const char* options :
       {"--size 8", "--size 4096", "--rocks 0.7", "--rocks -0.1", "--light midnight", "--noise -1",
        "--seed banana", "--x 100", "--misalign-tilt 1e9"}) {
    const auto result = run_marsokhod("world " + kQuick + std::string(options) + out);
    EXPECT_EQ(result.exit_code, 2) << options << ": " << result.err;
    EXPECT_FALSE(result.err.empty()) << options;
  }
  EXPECT_EQ(run_marsokhod("world --size 64").exit_code, 2); // --out is required
}

TEST(WorldCommand, UnwritableOutputFolderIsARuntimeErrorNamingIt) {
  const fs::path base = world_folder("unwritable");
  fs::create_directories(base);
  const fs::path blocker = base / "a-file";
  std::ofstream(blocker) << "not a folder";
  const fs::path dir = blocker / "scene";
  const auto result = run_marsokhod("world " + kQuick + "--out '" + dir.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(dir.string()), std::string::npos) << result.err;
}

TEST(WorldCommand, MissingRigFileIsARuntimeErrorNamingIt) {
  const fs::path dir = world_folder("rig");
  const auto result =
      run_marsokhod("world " + kQuick + "--rig /nonexistent/rig.toml --out '" + dir.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("/nonexistent/rig.toml"), std::string::npos) << result.err;
}

} // namespace
