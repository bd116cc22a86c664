// Tests: `marsokhod calibrate` on a misaligned rendered pair, and its refusals of bad pairs.

#include "support/run_marsokhod.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

namespace {

namespace fs = std::filesystem;
using marsokhod::testing::quoted;
using marsokhod::testing::run_marsokhod;

fs::path calibrate_folder(const std::string& name) {
  return marsokhod::testing::fresh_folder("marsokhod-calibrate-tests", name);
}

// 1410" of tilt: 1.5 rows of vertical parallax at the centre of a 128 px image (f = 219.4 px).
constexpr double kTiltArcsec = 1410.0;

// A misaligned 128 px scene, rendered once per test process into a folder of its own.
const fs::path& scene() {
  static const fs::path dir = [] {
    const fs::path folder = calibrate_folder(
        std::string("scene-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    const auto result = run_marsokhod(
        "world --terrain-size 16 --size 128 --seed 3 --misalign-tilt 1410 --out " + quoted(folder));
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return folder;
  }();
  return dir;
}

std::string pair() {
  return quoted(scene() / "left.pgm") + " " + quoted(scene() / "right.pgm");
}

fs::path write_file(const fs::path& folder, const std::string& name, const std::string& text) {
  std::ofstream(folder / name, std::ios::binary) << text;
  return folder / name;
}

TEST(CalibrateCommand, MeasuresTheTiltsShiftAndNavUsesTheFile) {
  const fs::path dir = calibrate_folder("good");
  const fs::path file = dir / "cal.toml";
  const auto result = run_marsokhod("calibrate " + pair() + " --out " + quoted(file) + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = nlohmann::json::parse(result.out);
  const double focal_px = 12.0 / 7.0 * 128.0;
  const double tilt = kTiltArcsec * std::numbers::pi / (180.0 * 3600.0);
  EXPECT_NEAR(summary["shift_centre_rows"].get<double>(), focal_px * tilt, 0.15);
  EXPECT_TRUE(fs::is_regular_file(file));
  const auto nav = run_marsokhod("nav " + pair() + " --out " + quoted(dir / "nav") +
                                 " --calibration " + quoted(file));
  EXPECT_EQ(nav.exit_code, 0) << nav.err;
}

TEST(CalibrateCommand, RefusesAPairOfDifferentSizes) {
  const fs::path dir = calibrate_folder("sizes");
  const auto resize =
      run_marsokhod("world --terrain-size 16 --size 64 --seed 3 --out " + quoted(dir / "small"));
  ASSERT_EQ(resize.exit_code, 0) << resize.err;
  const auto result =
      run_marsokhod("calibrate " + quoted(scene() / "left.pgm") + " " +
                    quoted(dir / "small" / "right.pgm") + " --out " + quoted(dir / "cal.toml"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("differs in size"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir / "cal.toml"));
}

TEST(CalibrateCommand, RefusesAMissingImageNamingIt) {
  const fs::path dir = calibrate_folder("missing");
  const auto result =
      run_marsokhod("calibrate " + quoted(dir / "nope.pgm") + " " + quoted(scene() / "right.pgm") +
                    " --out " + quoted(dir / "cal.toml"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("nope.pgm"), std::string::npos) << result.err;
}

TEST(CalibrateCommand, RefusesAUniformPairForLackOfTexture) {
  const fs::path dir = calibrate_folder("uniform");
  std::string grey = "P5 64 64 255\n" + std::string(64 * 64, '\x80');
  const fs::path image = write_file(dir, "grey.pgm", grey);
  const auto result = run_marsokhod("calibrate " + quoted(image) + " " + quoted(image) + " --out " +
                                    quoted(dir / "cal.toml"));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("too little texture"), std::string::npos) << result.err;
}

struct BadCalibration {
  const char* name;
  std::string text; // empty: the file does not exist
  const char* problem;
};

class NavCalibrationErrors : public ::testing::TestWithParam<BadCalibration> {};

TEST_P(NavCalibrationErrors, ExitWithStatusOneNamingTheFileAndTheProblem) {
  const fs::path dir = calibrate_folder(std::string("nav-") + GetParam().name);
  const fs::path file =
      GetParam().text.empty() ? dir / "absent.toml" : write_file(dir, "cal.toml", GetParam().text);
  const auto result = run_marsokhod("nav " + pair() + " --out " + quoted(dir / "out") +
                                    " --calibration " + quoted(file));
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find(file.string()), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(GetParam().problem), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

const std::string kTable = "[vertical_parallax]\nwidth_px = 128\nheight_px = 128\nc0 = 1.5\n"
                           "cx = 0.0\ncy = 0.0\ncxx = 0.0\ncxy = 0.0\ncyy = 0.0\n";

INSTANTIATE_TEST_SUITE_P(
    CalibrateCommand, NavCalibrationErrors,
    ::testing::Values(
        // The reader's wording for a missing file varies; the file named and exit 1 do not.
        BadCalibration{"missing", "", ""},
        BadCalibration{"malformed", "[vertical_parallax]\nc0 = = 1\n", "TOML syntax error"},
        BadCalibration{"wrong_size",
                       "[vertical_parallax]\nwidth_px = 256\nheight_px = 256\n"
                       "c0 = 1.5\ncx = 0.0\ncy = 0.0\ncxx = 0.0\ncxy = 0.0\n"
                       "cyy = 0.0\n",
                       "the calibration is for 256x256 images but the images are 128x128"},
        BadCalibration{"incomplete", kTable.substr(0, kTable.find("cyy")),
                       ":1: 'vertical_parallax.cyy': missing"}),
    [](const auto& test) { return std::string(test.param.name); });

} // namespace
