// Tests: rig files: the shipped rigs, round trips through TOML, and errors naming file, line, key.

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/io/files/input_error.hpp"

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

TEST(RigFile, ToTomlSpellsEveryNumberAsAShortestTomlFloat) {
  RigParameters p;
  p.mast_height_m = 2.0;
  p.pitch_down_deg = 0.1 + 0.2;
  p.baseline_m = 1e-3;
  p.width_px = 128;
  p.right_misalignment.tilt_arcsec = -1410.0;
  EXPECT_EQ(StereoRig(p).to_toml(), "# Stereo rig (format: docs/formats.md, \"Rig files\").\n"
                                    "[rig]\n"
                                    "mast_height_m = 2.0\n"
                                    "mast_forward_m = 0.0\n"
                                    "pitch_down_deg = 0.30000000000000004\n"
                                    "focal_mm = 12.0\n"
                                    "sensor_mm = 7.0\n"
                                    "baseline_m = 0.001\n"
                                    "width_px = 128\n"
                                    "height_px = 256\n"
                                    "\n"
                                    "[rig.right_misalignment]\n"
                                    "pan_arcsec = 0.0\n"
                                    "tilt_arcsec = -1410.0\n"
                                    "roll_arcsec = 0.0\n");
}

template <class Error>
Error load_error(const fs::path& path) {
  try {
    StereoRig::load(path);
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "no such error for " << path;
  return Error("", 0, "", "");
}

// The same form as every keyed file (a platform file, a campaign file): file, line, key, and
// io::TomlTable's words for a range.
TEST(RigFile, AValueOutOfRangeReadsLikeEveryKeyedFile) {
  const fs::path path = write_rig_file("zero_baseline", "[rig]\nbaseline_m = 0\n");
  const RigFileError error = load_error<RigFileError>(path);
  EXPECT_EQ(std::string(error.what()),
            path.string() +
                ":2: 'rig.baseline_m': 0 is out of range: it must be between 0.001 and 100");
  EXPECT_EQ(error.file(), path.string());
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.key(), "rig.baseline_m");
  EXPECT_THROW(StereoRig::load(path), io::KeyedFileError);
}

struct BadRig {
  const char* name;
  const char* text;
  int line;        ///< of the key's value (or of the table it lacks)
  const char* key; ///< as the message names it
  const char* problem;
};

std::string bad_rig_name(const ::testing::TestParamInfo<BadRig>& param) {
  return param.param.name;
}

class RigFileErrors : public ::testing::TestWithParam<BadRig> {};

TEST_P(RigFileErrors, NameTheFileTheLineAndTheKey) {
  const BadRig& bad = GetParam();
  const fs::path path = write_rig_file(bad.name, bad.text);
  const RigFileError error = load_error<RigFileError>(path);
  EXPECT_EQ(std::string(error.what()),
            path.string() + ":" + std::to_string(bad.line) + ": '" + bad.key + "': " + bad.problem);
}

constexpr const char* kOutOf = " is out of range: it must be between ";

INSTANTIATE_TEST_SUITE_P(
    BadFiles, RigFileErrors,
    ::testing::Values(
        BadRig{"unknown_key", "[rig]\nbaseline_m = 0.5\ncolour = 1\n", 3, "rig.colour",
               "unknown key (known keys: mast_height_m, mast_forward_m, pitch_down_deg, "
               "focal_mm, sensor_mm, baseline_m, width_px, height_px, [rig.right_misalignment])"},
        BadRig{"unknown_misalignment_key", "[rig]\n[rig.right_misalignment]\nyaw_arcsec = 1\n", 3,
               "rig.right_misalignment.yaw_arcsec",
               "unknown key (known keys: pan_arcsec, tilt_arcsec, roll_arcsec)"},
        BadRig{"unknown_table", "[rig]\nfocal_mm = 12.0\n\n[camera]\nfocal_mm = 12.0\n", 4,
               "camera", "unknown key: a rig file holds one [rig] table"},
        BadRig{"string_focal", "[rig]\nfocal_mm = \"12\"\n", 2, "rig.focal_mm",
               "must be a finite number, not a string"},
        BadRig{"float_width", "[rig]\nwidth_px = 256.0\n", 2, "rig.width_px",
               "must be an integer, not a floating-point number"},
        BadRig{"negative_baseline", "[rig]\n\nbaseline_m = -0.5\n", 3, "rig.baseline_m",
               "-0.5 is out of range: it must be between 0.001 and 100"},
        BadRig{"zero_focal", "[rig]\nfocal_mm = 0.0\n", 2, "rig.focal_mm",
               "0 is out of range: it must be between 0.1 and 10000"},
        BadRig{"negative_sensor", "[rig]\nsensor_mm = -7.0\n", 2, "rig.sensor_mm",
               "-7 is out of range: it must be between 0.1 and 1000"},
        BadRig{"tiny_image", "[rig]\nwidth_px = 8\n", 2, "rig.width_px",
               "8 is out of range: it must be between 16 and 16384"},
        BadRig{"huge_image", "[rig]\nwidth_px = 256\nheight_px = 20000\n", 3, "rig.height_px",
               "20000 is out of range: it must be between 16 and 16384"},
        // 2^32 + 256 would be 256 after a cast to 32 bits.
        BadRig{"wrapping_image", "[rig]\nwidth_px = 4294967552\n", 2, "rig.width_px",
               "4294967552 is out of range: it must be between 16 and 16384"},
        BadRig{"steep_pitch", "[rig]\npitch_down_deg = 90.0\n", 2, "rig.pitch_down_deg",
               "90 is out of range: it must be between -89 and 89"},
        BadRig{"steep_negative_pitch", "[rig]\npitch_down_deg = -95\n", 2, "rig.pitch_down_deg",
               "-95 is out of range: it must be between -89 and 89"},
        BadRig{"ground_level_mast", "[rig]\nmast_height_m = 0.0\n", 2, "rig.mast_height_m",
               "0 is out of range: it must be between 0.01 and 100"},
        BadRig{"not_a_number", "[rig]\nbaseline_m = nan\n", 2, "rig.baseline_m",
               "must be a finite number, not nan"},
        BadRig{"infinite", "[rig]\nfocal_mm = inf\n", 2, "rig.focal_mm",
               "must be a finite number, not inf"},
        BadRig{"large_misalignment", "[rig.right_misalignment]\ntilt_arcsec = 7200\n", 2,
               "rig.right_misalignment.tilt_arcsec",
               "7200 is out of range: it must be between -3600 and 3600"},
        BadRig{"misalignment_not_table", "[rig]\nright_misalignment = 5\n", 2,
               "rig.right_misalignment", "must be a table, not an integer"},
        BadRig{"rig_not_table", "rig = 1\n", 1, "rig", "must be a table, not an integer"}),
    bad_rig_name);

// What is not TOML is the bounded reader's io::InputError: file, line, toml++'s description
// and the offending line.
TEST(RigFile, SyntaxErrorsNameTheFileTheLineAndTheText) {
  const fs::path syntax =
      write_rig_file("syntax_error", "[rig]\nfocal_mm = 12.0\nbaseline_m = = 0.5\n");
  const io::InputError error = [&] {
    try {
      StereoRig::load(syntax);
    } catch (const io::InputError& caught) {
      return caught;
    }
    ADD_FAILURE() << "accepted a syntax error";
    return io::InputError("", "");
  }();
  const std::string message = error.what();
  EXPECT_EQ(message.rfind(syntax.string() + ":3: TOML syntax error", 0), 0U) << message;
  EXPECT_NE(message.find("\"baseline_m = = 0.5\""), std::string::npos) << message;

  const fs::path duplicate =
      write_rig_file("duplicate_key", "[rig]\nfocal_mm = 12.0\nfocal_mm = 11.0\n");
  try {
    StereoRig::load(duplicate);
    ADD_FAILURE() << "accepted a duplicate key";
  } catch (const io::InputError& caught) {
    const std::string text = caught.what();
    EXPECT_EQ(text.rfind(duplicate.string() + ":3: ", 0), 0U) << text;
    EXPECT_NE(text.find("focal_mm"), std::string::npos) << text;
  }
}

TEST(RigFile, FileWithoutRigTableIsRejected) {
  const fs::path path = write_rig_file("empty", "# nothing here\n");
  EXPECT_EQ(std::string(load_error<RigFileError>(path).what()),
            path.string() + ": 'rig': missing [rig] table");
}

TEST(RigFile, MissingFileIsRejectedByName) {
  const fs::path path = fs::temp_directory_path() / "marsokhod-rig-file-test" / "absent.toml";
  fs::remove(path);
  try {
    StereoRig::load(path);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const io::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path.string() + ": ", 0), 0U) << error.what();
  }
}

} // namespace
} // namespace marsokhod::imaging
