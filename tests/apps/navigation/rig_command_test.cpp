// Tests: `marsokhod rig`, the paper rig it describes, and bad rig files and options.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

// `marsokhod rig` against the paper's rig worked out by hand: cameras 1 m up over the rover
// centre, 10 deg down, f = 12 mm on a 7 mm CCD (12 / 7 * N px), baseline 0.5 m.

namespace marsokhod {
namespace {

namespace fs = std::filesystem;
using testing::run_marsokhod;

constexpr double kPi = std::numbers::pi;
const double kDown = 10.0 * kPi / 180.0;

nlohmann::json rig_json(const std::string& arguments) {
  const auto result = run_marsokhod("rig --json " + arguments);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(result.out);
}

void expect_paper_rig(const nlohmann::json& json, int side) {
  const double f = 12.0 / 7.0 * side;
  const double cy = (side - 1) / 2.0;
  EXPECT_NEAR(json.at("focal_px").get<double>(), f, 1e-9);
  EXPECT_NEAR(json.at("vertical_fov_deg").get<double>(), 2.0 * std::atan(3.5 / 12.0) * 180.0 / kPi,
              1e-9);
  EXPECT_NEAR(json.at("ground_visible_from_m").get<double>(),
              1.0 / std::tan(kDown + std::atan(3.5 / 12.0)), 1e-9);
  EXPECT_NEAR(json.at("horizon_row").get<double>(), cy - f * std::tan(kDown), 1e-9);

  // Row v looks atan((v - cy) / f) below the optical axis; d = (B / h) (f sin a + y cos a).
  const auto& rows = json.at("rows");
  ASSERT_EQ(rows.size(), static_cast<size_t>(side / 16 + 1));
  for (const auto& row : rows) {
    const int v = row.at("row").get<int>();
    EXPECT_TRUE(v % 16 == 0 || v == side - 1) << v;
    const double y = v - cy;
    const double fall = f * std::sin(kDown) + y * std::cos(kDown);
    EXPECT_NEAR(row.at("ground_disparity_px").get<double>(), fall > 0 ? 0.5 * fall : 0.0, 1e-9);
    if (fall > 0)
      EXPECT_NEAR(row.at("ground_distance_m").get<double>(),
                  1.0 / std::tan(kDown + std::atan(y / f)), 1e-9);
    else
      EXPECT_TRUE(row.at("ground_distance_m").is_null()) << v;
  }

  // Stone top (14, 0, 0.3) and foot (14, 0, 0) seen from (0, 0.25, 1) along (cos a, 0, -sin a);
  // the ground in the top's row is 14 / 0.7 = 20 m ahead.
  const auto& stone = json.at("stone_14m");
  const double fb = f * 0.5;
  const double top = fb / (14.0 * std::cos(kDown) + 0.7 * std::sin(kDown));
  const double foot = fb / (14.0 * std::cos(kDown) + std::sin(kDown));
  const double ground = fb / (20.0 * std::cos(kDown) + std::sin(kDown));
  EXPECT_NEAR(stone.at("top_disparity_px").get<double>(), top, 1e-9);
  EXPECT_NEAR(stone.at("bottom_disparity_px").get<double>(), foot, 1e-9);
  EXPECT_NEAR(stone.at("top_minus_bottom_px").get<double>(), top - foot, 1e-9);
  EXPECT_NEAR(stone.at("ground_behind_distance_m").get<double>(), 20.0, 1e-9);
  EXPECT_NEAR(stone.at("top_minus_ground_px").get<double>(), top - ground, 1e-9);
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-rig-command-test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(RigCommand, JsonDescribesThePapersRigAtBothSizes) {
  expect_paper_rig(rig_json(""), 256);
  expect_paper_rig(rig_json("--size 128"), 128);
  const fs::path rigs = fs::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "rigs";
  expect_paper_rig(rig_json("--rig '" + (rigs / "marsokhod-128.toml").string() + "'"), 128);
  expect_paper_rig(rig_json("--rig '" + (rigs / "marsokhod-128.toml").string() + "' --size 256"),
                   256);
}

TEST(RigCommand, TextReportShowsTheKeyFigures) {
  const auto result = run_marsokhod("rig --size 128");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("219.429 px"), std::string::npos) << result.out; // 12 / 7 * 128
  EXPECT_NE(result.out.find("32.52 deg"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("2.027 m"), std::string::npos) << result.out;
}

// Pitched 20 deg up with a 32.5 deg field of view, the lowest row looks 3.7 deg above the
// horizontal: no row meets the ground, which the report says in words (JSON: null).
TEST(RigCommand, RigThatSeesNoGroundSaysSoInsteadOfPrintingInfinity) {
  const fs::path path = write_file("up.toml", "[rig]\npitch_down_deg = -20\n");
  const auto result = run_marsokhod("rig --rig '" + path.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("ground visible from     nowhere"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("inf"), std::string::npos) << result.out;
  EXPECT_TRUE(rig_json("--rig '" + path.string() + "'")["ground_visible_from_m"].is_null());
  // The stone's top is atan(0.7 / 14) = 2.9 deg below the horizontal, 22.9 deg below an axis
  // 20 deg up: beyond the 16.3 deg half field of view, below the bottom row.
  EXPECT_NE(result.out.find("outside the image: top in row"), std::string::npos) << result.out;
}

TEST(RigCommand, ThePapersRigSeesTheStoneInsideTheImage) {
  const auto result = run_marsokhod("rig");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.find("outside the image"), std::string::npos) << result.out;
}

TEST(RigCommand, BadRigFileExitsOneNamingFileAndKey) {
  const fs::path path = write_file("bad.toml", "[rig]\nbaseline_m = -0.5\n");
  const auto result = run_marsokhod("rig --rig '" + path.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(path.string() + ":2: 'rig.baseline_m': -0.5 is out of range: it must "
                                            "be between 0.001 and 100"),
            std::string::npos)
      << result.err;
  EXPECT_TRUE(result.out.empty());

  const auto missing =
      run_marsokhod("rig --rig '" + (path.parent_path() / "absent.toml").string() + "'");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("absent.toml"), std::string::npos) << missing.err;
}

TEST(RigCommand, BadOptionsExitTwo) {
  EXPECT_EQ(run_marsokhod("rig --size 100").exit_code, 2);
  EXPECT_EQ(run_marsokhod("rig --size many").exit_code, 2);
  EXPECT_EQ(run_marsokhod("rig --colour").exit_code, 2);
  EXPECT_EQ(run_marsokhod("rig --rig").exit_code, 2);
}

} // namespace
} // namespace marsokhod
