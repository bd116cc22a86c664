// Tests: the vertical parallax map, its removal, its calibration file and its calibration.

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/nav/calibration/vertical_parallax_calibration.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace marsokhod::nav {
namespace {

namespace fs = std::filesystem;

// ---- The map and its removal ---------------------------------------------------------------

TEST(VerticalParallaxMap, EvaluatesTheQuadraticAboutTheImageCentre) {
  VerticalParallaxMap map{9, 5, {1.0, 0.5, -0.25, 0.125, 0.0625, 0.03125}};
  // Centre (4, 2): only c0. Pixel (0, 0): u = -4, v = -2.
  EXPECT_DOUBLE_EQ(map.shift_at(4, 2), 1.0);
  EXPECT_DOUBLE_EQ(map.shift_at(0, 0), 1.0 - 2.0 + 0.5 + 2.0 + 0.5 + 0.125);
  // Largest at the corner (8, 4): u = 4, v = 2.
  EXPECT_DOUBLE_EQ(map.largest_shift(), 1.0 + 2.0 - 0.5 + 2.0 + 0.5 + 0.125);
  EXPECT_FALSE(map.is_identity());
}

// Rows of a vertical ramp: grey 10 + 4 y, so a shift of s rows reads grey 10 + 4 (y + s).
imaging::Image<std::uint8_t> row_ramp(int width, int height) {
  imaging::Image<std::uint8_t> image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image(x, y) = static_cast<std::uint8_t>(10 + 4 * y);
  return image;
}

class RemoveVerticalShift : public ::testing::TestWithParam<VerticalInterpolation> {};

// Both interpolations reproduce a linear ramp exactly away from the border.
TEST_P(RemoveVerticalShift, ReadsEachPixelFromTheShiftedRowInterpolatingBetweenRows) {
  const imaging::Image<std::uint8_t> right = row_ramp(8, 20);
  const VerticalParallaxMap map{8, 20, {1.5, 0, 0, 0, 0, 0}};
  const imaging::Image<std::uint8_t> aligned = remove_vertical_parallax(right, map, GetParam());
  for (int y = 1; y < 17; ++y)
    for (int x = 0; x < 8; ++x)
      ASSERT_EQ(aligned(x, y), 10 + 4 * y + 6) << x << "," << y;
  // Row 19 + 1.5 lies below the image: the bottom row repeats.
  EXPECT_EQ(aligned(0, 19), 10 + 4 * 19);
}

INSTANTIATE_TEST_SUITE_P(BothInterpolations, RemoveVerticalShift,
                         ::testing::Values(VerticalInterpolation::linear,
                                           VerticalInterpolation::cubic));

TEST(RemoveVerticalParallax, CubicKeepsABrightRowSharperThanLinear) {
  // One bright row (200) at row 6, shifted half a row. Keys' cubic at t = 1/2 weighs the four
  // rows around -1/16, 9/16, 9/16, -1/16; linear weighs the two middle ones 1/2, 1/2.
  imaging::Image<std::uint8_t> right(4, 12, 1, 0);
  for (int x = 0; x < 4; ++x)
    right(x, 6) = 200;
  const VerticalParallaxMap map{4, 12, {0.5, 0, 0, 0, 0, 0}};
  const imaging::Image<std::uint8_t> linear =
      remove_vertical_parallax(right, map, VerticalInterpolation::linear);
  const imaging::Image<std::uint8_t> cubic =
      remove_vertical_parallax(right, map, VerticalInterpolation::cubic);
  EXPECT_EQ(linear(1, 5), 100);
  EXPECT_EQ(linear(1, 6), 100);
  EXPECT_EQ(cubic(1, 5), 113); // 200 * 9/16 = 112.5, rounded up
  EXPECT_EQ(cubic(1, 6), 113);
  EXPECT_EQ(cubic(1, 4), 0); // 200 * -1/16 clamps to black
  EXPECT_EQ(cubic(1, 7), 0);
}

TEST(RemoveVerticalParallax, FollowsARollThatShiftsEachColumnDifferently) {
  const imaging::Image<std::uint8_t> right = row_ramp(9, 30);
  // Shift = 0.25 u rows: column 0 (u = -4) reads one row up, column 8 one row down.
  const VerticalParallaxMap map{9, 30, {0, 0.25, 0, 0, 0, 0}};
  const imaging::Image<std::uint8_t> aligned = remove_vertical_parallax(right, map);
  EXPECT_EQ(aligned(0, 10), 10 + 4 * 9);
  EXPECT_EQ(aligned(4, 10), 10 + 4 * 10);
  EXPECT_EQ(aligned(8, 10), 10 + 4 * 11);
  EXPECT_EQ(aligned(6, 10), 10 + 4 * 10 + 2); // half a row down
}

TEST(RemoveVerticalParallax, ReportsOnePixelOfWorkPerOutputPixel) {
  const imaging::Image<std::uint8_t> right = row_ramp(12, 7);
  CountingMeter meter;
  static_cast<void>(remove_vertical_parallax(right, VerticalParallaxMap{12, 7, {}},
                                             VerticalInterpolation::cubic, meter));
  EXPECT_EQ(meter.count(Work::pyramid_pixel), 12U * 7U);
  EXPECT_EQ(meter.total(), 12U * 7U);
}

TEST(RemoveVerticalParallax, RefusesAMapOfAnotherSize) {
  const imaging::Image<std::uint8_t> right = row_ramp(12, 7);
  EXPECT_THROW(remove_vertical_parallax(right, VerticalParallaxMap{12, 8, {}}), CalibrationError);
}

// ---- Calibration files ---------------------------------------------------------------------

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-parallax-tests";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The message of a file's refusal: a CalibrationFileError for what it holds, an io::InputError
// for a file that cannot be read or is not TOML.
std::string load_error(const fs::path& path) {
  try {
    static_cast<void>(load_vertical_parallax(path));
  } catch (const CalibrationFileError& error) {
    return error.what();
  } catch (const io::InputError& error) {
    return error.what();
  }
  return "no error";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

constexpr const char* kGoodTable = "[vertical_parallax]\nwidth_px = 128\nheight_px = 96\n"
                                   "c0 = 1.5\ncx = 0.001\ncy = 0\ncxx = 0.0\ncxy = 2e-5\n"
                                   "cyy = 3e-5\n";

TEST(CalibrationFile, ReadsBackExactlyWhatItWrote) {
  const VerticalParallaxMap map{128, 96, {1.4937, -1.0 / 3.0, 2.5e-3, 1e-7, -3.3e-6, 4.1e-5}};
  const fs::path path = write_file("round_trip.toml", vertical_parallax_to_toml(map, "a\nb"));
  const VerticalParallaxMap back = load_vertical_parallax(path);
  EXPECT_EQ(back.width, 128);
  EXPECT_EQ(back.height, 96);
  EXPECT_EQ(back.coefficients, map.coefficients);
  EXPECT_EQ(load_vertical_parallax(write_file("hand.toml", kGoodTable)).coefficients[0], 1.5);
}

TEST(CalibrationFile, WritesEveryCoefficientAsAShortestTomlFloat) {
  const VerticalParallaxMap map{128, 96, {2.0, 0.1 + 0.2, -1e-7, 0.0, 5e-324, -64.0}};
  EXPECT_EQ(vertical_parallax_to_toml(map, "fitted"),
            "# Vertical parallax calibration (format: docs/navigation.md, \"Calibration file\").\n"
            "# fitted\n"
            "[vertical_parallax]\nwidth_px = 128\nheight_px = 96\n"
            "# shift(x, y) = c0 + cx u + cy v + cxx u^2 + cxy u v + cyy v^2 rows (right image "
            "content lower),\n# u = x - (width_px - 1) / 2, v = y - (height_px - 1) / 2\n"
            "c0 = 2.0\ncx = 0.30000000000000004\ncy = -1e-07\ncxx = 0.0\ncxy = 5e-324\n"
            "cyy = -64.0\n");
}

// The same form as every keyed file (a platform file, a campaign file): file, line, key, and
// io::TomlTable's words for a range.
TEST(CalibrationFile, AValueOutOfRangeReadsLikeEveryKeyedFile) {
  const fs::path path = write_file("big_c0.toml", replaced(kGoodTable, "c0 = 1.5", "c0 = 2e6"));
  try {
    static_cast<void>(load_vertical_parallax(path));
    ADD_FAILURE() << "accepted c0 = 2e6";
  } catch (const CalibrationFileError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ":4: 'vertical_parallax.c0': 2000000 is out of range: it must be "
                              "between -1000000 and 1000000");
    EXPECT_EQ(error.line(), 4);
    EXPECT_EQ(error.key(), "vertical_parallax.c0");
  }
  EXPECT_THROW(static_cast<void>(load_vertical_parallax(path)), io::KeyedFileError);
}

TEST(CalibrationFile, AMissingFileIsNamed) {
  const fs::path path = fs::temp_directory_path() / "marsokhod-parallax-tests" / "absent.toml";
  EXPECT_EQ(load_error(path).rfind(path.string() + ": cannot open the calibration file", 0), 0U)
      << load_error(path);
}

// The bounded reader refuses what is not a regular file without blocking or reading it.
TEST(CalibrationFile, ADeviceIsRefusedWithoutBeingRead) {
  const std::string message = load_error("/dev/zero");
  EXPECT_EQ(message.rfind("/dev/zero: is a device", 0), 0U) << message;
}

// Two terms of 1e300 rows per pixel squared at the corner of a square image overflow to +inf
// and -inf; their sum is NaN, which no comparison with the 64-row limit refuses. The
// coefficient range keeps every term finite.
TEST(CalibrationFile, CoefficientsThatCouldCancelToNanAreRefusedByName) {
  const std::string square = replaced(kGoodTable, "height_px = 96", "height_px = 128");
  const std::string text =
      replaced(replaced(square, "cxx = 0.0", "cxx = 1e300"), "cyy = 3e-5", "cyy = -1e300");
  const std::string message = load_error(write_file("cancelling.toml", text));
  EXPECT_NE(message.find(":7: 'vertical_parallax.cxx': 1e+300 is out of range: it must be "
                         "between -1000000 and 1000000"),
            std::string::npos)
      << message;
}

// The general rule: every coefficient key accepts up to 1e6 in magnitude as a number (such a
// map is still refused for its shift) and nothing beyond; at the largest legal coefficients
// and image the shift is finite, so the shift limit always decides.
TEST(CalibrationFile, EveryCoefficientIsBoundedAndTheLargestLegalMapStaysFinite) {
  for (const char* key : {"c0", "cx", "cy", "cxx", "cxy", "cyy"}) {
    const std::string line = std::string(key) + " = ";
    const std::string table = std::string(kGoodTable);
    const std::size_t start = table.find("\n" + line) + 1;
    const std::size_t end = table.find('\n', start);
    const std::string at_limit = table.substr(0, start) + line + "-1e6" + table.substr(end);
    const std::string beyond = table.substr(0, start) + line + "1.000001e6" + table.substr(end);
    EXPECT_NE(load_error(write_file("limit.toml", at_limit)).find("more than the 64"),
              std::string::npos)
        << key;
    EXPECT_NE(load_error(write_file("beyond.toml", beyond))
                  .find(fmt::format("'vertical_parallax.{}': 1000001 is out of range", key)),
              std::string::npos)
        << key;
  }
  const VerticalParallaxMap largest{16384, 16384, {1e6, -1e6, 1e6, -1e6, 1e6, -1e6}};
  EXPECT_TRUE(std::isfinite(largest.largest_shift()));
}

struct BadFile {
  const char* name;
  std::string text;
  const char* place; ///< after the file: ":LINE: 'KEY': ", ":LINE: " or ": 'KEY': "
  const char* problem;
};

class CalibrationFileErrors : public ::testing::TestWithParam<BadFile> {};

TEST_P(CalibrationFileErrors, NameTheFileTheLineAndTheKey) {
  const fs::path path = write_file(std::string(GetParam().name) + ".toml", GetParam().text);
  const std::string message = load_error(path);
  EXPECT_EQ(message.rfind(path.string() + GetParam().place, 0), 0U) << message;
  EXPECT_NE(message.find(GetParam().problem), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    VerticalParallax, CalibrationFileErrors,
    ::testing::Values(
        BadFile{"syntax", "[vertical_parallax\n", ":1: ", "TOML syntax error"},
        BadFile{"empty", "", ": 'vertical_parallax': ", "missing [vertical_parallax] table"},
        BadFile{"not_a_table", "vertical_parallax = 1\n",
                ":1: 'vertical_parallax': ", "must be a table, not an integer"},
        BadFile{"other_table", std::string("[rig]\n") + kGoodTable, ":1: 'rig': ",
                "unknown key: a calibration file holds one [vertical_parallax] table"},
        BadFile{"unknown_key", std::string(kGoodTable) + "c3 = 1.0\n",
                ":10: 'vertical_parallax.c3': ",
                "unknown key (known keys: width_px, height_px, c0, cx, cy, cxx, cxy, cyy)"},
        BadFile{"missing", replaced(kGoodTable, "cyy = 3e-5\n", ""),
                ":1: 'vertical_parallax.cyy': ", "missing"},
        BadFile{"string", replaced(kGoodTable, "c0 = 1.5", "c0 = \"1.5\""),
                ":4: 'vertical_parallax.c0': ", "must be a finite number, not a string"},
        BadFile{"nan", replaced(kGoodTable, "c0 = 1.5", "c0 = nan"),
                ":4: 'vertical_parallax.c0': ", "must be a finite number, not nan"},
        BadFile{"infinite", replaced(kGoodTable, "c0 = 1.5", "c0 = -inf"),
                ":4: 'vertical_parallax.c0': ", "must be a finite number, not -inf"},
        // 2^32 + 128 would be 128 after a cast to 32 bits.
        BadFile{"wrapping_size", replaced(kGoodTable, "width_px = 128", "width_px = 4294967424"),
                ":2: 'vertical_parallax.width_px': ",
                "4294967424 is out of range: it must be between 16 and 16384"},
        BadFile{"float_size", replaced(kGoodTable, "width_px = 128", "width_px = 128.0"),
                ":2: 'vertical_parallax.width_px': ",
                "must be an integer, not a floating-point number"},
        BadFile{"tiny", replaced(kGoodTable, "height_px = 96", "height_px = 2"),
                ":3: 'vertical_parallax.height_px': ",
                "2 is out of range: it must be between 16 and 16384"},
        // Each coefficient is in range; the map as a whole is refused at its table.
        BadFile{"huge_shift", replaced(kGoodTable, "c0 = 1.5", "c0 = 80.0"),
                ":1: ", "the map shifts rows by up to 80"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(CalibrationFile, AMapOfAnotherSizeIsRefusedNamingTheSource) {
  const VerticalParallaxMap map{128, 96, {}};
  try {
    check_map_size(map, 256, 256, "cal.toml");
    FAIL() << "no error";
  } catch (const CalibrationError& error) {
    EXPECT_STREQ(error.what(),
                 "cal.toml: the calibration is for 128x96 images but the images are 256x256");
  }
}

// ---- Calibration on rendered pairs ---------------------------------------------------------

TEST(CalibrateVerticalParallax, RefusesPairsWithoutTextureOrOfDifferentSizes) {
  const imaging::Image<std::uint8_t> grey(64, 64, 1, 128);
  EXPECT_THROW(calibrate_vertical_parallax(grey, grey), CalibrationError);
  const imaging::Image<std::uint8_t> small(64, 48, 1, 128);
  EXPECT_THROW(calibrate_vertical_parallax(grey, small), CalibrationError);
  const imaging::Image<std::uint8_t> tiny(16, 16, 1, 128);
  EXPECT_THROW(calibrate_vertical_parallax(tiny, tiny), CalibrationError);
}

} // namespace
} // namespace marsokhod::nav
