// Tests: rig files: the shipped rigs, round trips through TOML, and errors naming the line.

#include "marsokhod/imaging/rig/camera.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace marsokhod::imaging {
namespace {

namespace fs = std::filesystem;

fs::path write_rig_file(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-rig-file-test";
  fs::create_directories(dir);
  const fs::path path = dir / (name + ".toml");
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

fs::path shipped_rig(const std::string& name) {
  return fs::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "rigs" / name;
}

TEST(RigFile, ShippedRigsAreThePapersRigAtBothSizes) {
  RigParameters paper;
  EXPECT_EQ(StereoRig::load(shipped_rig("marsokhod-256.toml")).parameters(), paper);
  paper.width_px = 128;
  paper.height_px = 128;
  EXPECT_EQ(StereoRig::load(shipped_rig("marsokhod-128.toml")).parameters(), paper);
}

TEST(RigFile, ToTomlReadsBackToTheSameRig) {
  RigParameters p;
  p.mast_height_m = 0.1 + 0.2; // not exactly 0.3: the text must keep every bit
  p.mast_forward_m = -0.125;
  p.pitch_down_deg = 12.345678901234567;
  p.focal_mm = 10.0 / 3.0;
  p.sensor_mm = 6.4;
  p.baseline_m = 2.0;
  p.width_px = 320;
  p.height_px = 240;
  p.right_misalignment = {-3.5, 17.0, 1.0 / 7.0};
  const StereoRig rig(p);
  const fs::path path = write_rig_file("round_trip", rig.to_toml());
  EXPECT_EQ(StereoRig::load(path).parameters(), p);
  EXPECT_EQ(StereoRig::load(path).to_toml(), rig.to_toml());
  EXPECT_EQ(StereoRig::load(write_rig_file("default", StereoRig().to_toml())).parameters(),
            RigParameters{});
}

TEST(RigFile, MissingKeysKeepThePapersValues) {
  const fs::path path = write_rig_file(
      "partial", "[rig]\nbaseline_m = 0.6\nmast_height_m = 2 # an integer is fine\n");
  RigParameters expected;
  expected.baseline_m = 0.6;
  expected.mast_height_m = 2.0;
  EXPECT_EQ(StereoRig::load(path).parameters(), expected);
}

struct BadRig {
  const char* name;
  const char* text;
  const char* key; ///< must appear in the message
  int line;        ///< reported as file:line:column
};

std::string bad_rig_name(const ::testing::TestParamInfo<BadRig>& param) {
  return param.param.name;
}

class RigFileErrors : public ::testing::TestWithParam<BadRig> {};

TEST_P(RigFileErrors, NameTheFileTheLineAndTheKey) {
  const BadRig& bad = GetParam();
  const fs::path path = write_rig_file(bad.name, bad.text);
  try {
    StereoRig::load(path);
    ADD_FAILURE() << "accepted " << bad.name;
  } catch (const RigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string() + ":" + std::to_string(bad.line) + ":"), std::string::npos)
        << message;
    EXPECT_NE(message.find(bad.key), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    BadFiles, RigFileErrors,
    ::testing::Values(
        BadRig{"unknown_key", "[rig]\nbaseline_m = 0.5\ncolour = 1\n", "rig.colour", 3},
        BadRig{"unknown_misalignment_key", "[rig]\n[rig.right_misalignment]\nyaw_arcsec = 1\n",
               "rig.right_misalignment.yaw_arcsec", 3},
        BadRig{"unknown_table", "[rig]\nfocal_mm = 12.0\n\n[camera]\nfocal_mm = 12.0\n", "camera",
               4},
        BadRig{"string_focal", "[rig]\nfocal_mm = \"12\"\n", "rig.focal_mm", 2},
        BadRig{"float_width", "[rig]\nwidth_px = 256.0\n", "rig.width_px", 2},
        BadRig{"negative_baseline", "[rig]\n\nbaseline_m = -0.5\n", "rig.baseline_m", 3},
        BadRig{"zero_baseline", "[rig]\nbaseline_m = 0\n", "rig.baseline_m", 2},
        BadRig{"zero_focal", "[rig]\nfocal_mm = 0.0\n", "rig.focal_mm", 2},
        BadRig{"negative_sensor", "[rig]\nsensor_mm = -7.0\n", "rig.sensor_mm", 2},
        BadRig{"tiny_image", "[rig]\nwidth_px = 8\n", "rig.width_px", 2},
        BadRig{"huge_image", "[rig]\nwidth_px = 256\nheight_px = 20000\n", "rig.height_px", 3},
        BadRig{"steep_pitch", "[rig]\npitch_down_deg = 90.0\n", "rig.pitch_down_deg", 2},
        BadRig{"steep_negative_pitch", "[rig]\npitch_down_deg = -95\n", "rig.pitch_down_deg", 2},
        BadRig{"ground_level_mast", "[rig]\nmast_height_m = 0.0\n", "rig.mast_height_m", 2},
        BadRig{"not_a_number", "[rig]\nbaseline_m = nan\n", "rig.baseline_m", 2},
        BadRig{"large_misalignment", "[rig.right_misalignment]\ntilt_arcsec = 7200\n",
               "rig.right_misalignment.tilt_arcsec", 2},
        BadRig{"misalignment_not_table", "[rig]\nright_misalignment = 5\n",
               "rig.right_misalignment", 2},
        BadRig{"rig_not_table", "rig = 1\n", "rig", 1},
        BadRig{"syntax_error", "[rig]\nfocal_mm = 12.0\nbaseline_m = = 0.5\n", "syntax error", 3},
        BadRig{"syntax_error_line", "[rig]\nfocal_mm = 12.0\nbaseline_m = = 0.5\n",
               "\"baseline_m = = 0.5\"", 3},
        BadRig{"duplicate_key", "[rig]\nfocal_mm = 12.0\nfocal_mm = 11.0\n", "focal_mm", 3}),
    bad_rig_name);

TEST(RigFile, FileWithoutRigTableIsRejected) {
  const fs::path path = write_rig_file("empty", "# nothing here\n");
  try {
    StereoRig::load(path);
    ADD_FAILURE() << "accepted a file without [rig]";
  } catch (const RigError& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("[rig]"), std::string::npos);
  }
}

TEST(RigFile, MissingFileIsRejectedByName) {
  const fs::path path = fs::temp_directory_path() / "marsokhod-rig-file-test" / "absent.toml";
  fs::remove(path);
  try {
    StereoRig::load(path);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const RigError& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos);
  }
}

} // namespace
} // namespace marsokhod::imaging
