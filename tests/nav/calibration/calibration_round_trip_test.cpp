// Tests: what a calibration fits, its file holds and reads back, over image and block sizes.

#include "nav/portable_random.hpp"

#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/nav/calibration/vertical_parallax_calibration.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace marsokhod::nav {
namespace {

namespace fs = std::filesystem;

/// A smooth random texture: bilinear between grey values on a 4-pixel lattice, so that block
/// matches are sub-pixel accurate; outside [textured_from, textured_to) columns it is flat.
class LatticeTexture {
public:
  LatticeTexture(int width, int height, std::uint64_t seed)
      : columns_(width / 4 + 3), rows_(height / 4 + 3) {
    std::mt19937_64 random(seed);
    lattice_.resize(static_cast<std::size_t>(columns_ * rows_));
    for (double& value : lattice_)
      value = 40.0 + 180.0 * testing::unit(random);
  }

  double at(double x, double y) const {
    const double gx = std::clamp(x / 4.0, 0.0, columns_ - 1.001);
    const double gy = std::clamp(y / 4.0, 0.0, rows_ - 1.001);
    const int ix = static_cast<int>(gx);
    const int iy = static_cast<int>(gy);
    const double fx = gx - ix;
    const double fy = gy - iy;
    const auto node = [&](int i, int j) {
      return lattice_[static_cast<std::size_t>(j * columns_ + i)];
    };
    return (1 - fy) * ((1 - fx) * node(ix, iy) + fx * node(ix + 1, iy)) +
           fy * ((1 - fx) * node(ix, iy + 1) + fx * node(ix + 1, iy + 1));
  }

private:
  int columns_;
  int rows_;
  std::vector<double> lattice_;
};

struct CalibrationPairShape {
  int width = 0;
  int height = 0;
  int textured_from = 0; ///< columns of texture; flat grey elsewhere
  int textured_to = 0;
  double disparity = 6.0;
  double shift = 0.0; ///< rows at the centre
  double roll = 0.0;  ///< rows per column
};

struct CalibrationPair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
};

std::uint8_t lattice_grey(double value) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
}

/// The right camera sees the left's content `disparity` columns to the left and
/// shift + roll (x - centre) rows lower.
CalibrationPair render_calibration_pair(const CalibrationPairShape& s, std::uint64_t seed) {
  const LatticeTexture texture(s.width + 64, s.height + 64, seed);
  const auto scene = [&](double x, double y) {
    if (x < s.textured_from || x >= s.textured_to)
      return 128.0;
    return texture.at(x + 32.0, y + 32.0);
  };
  CalibrationPair pair{imaging::Image<std::uint8_t>(s.width, s.height),
                       imaging::Image<std::uint8_t>(s.width, s.height)};
  const double centre = 0.5 * (s.width - 1);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      pair.left(x, y) = lattice_grey(scene(x, y));
      const double lower = s.shift + s.roll * (x - centre);
      pair.right(x, y) = lattice_grey(scene(x + s.disparity, y - lower));
    }
  return pair;
}

/// Calibrates the pair and, when that succeeds, writes the map and reads it back: a calibration
/// either refuses the pair with a CalibrationError or writes a file the navigation reads.
/// Returns whether the pair was calibrated.
bool expect_round_trip(const CalibrationPair& pair, const CalibrationOptions& options,
                       const std::string& what) {
  CalibrationResult result;
  try {
    result = calibrate_vertical_parallax(pair.left, pair.right, options);
  } catch (const CalibrationError& error) {
    EXPECT_NE(std::string(error.what()), "") << what;
    return false;
  }
  const fs::path file = fs::temp_directory_path() / "marsokhod_calibration_round_trip.toml";
  std::ofstream(file) << vertical_parallax_to_toml(result.map, what);
  VerticalParallaxMap read;
  try {
    read = load_vertical_parallax(file);
  } catch (const CalibrationFileError& error) {
    ADD_FAILURE() << what << ": the calibration wrote a file it cannot read: " << error.what();
    return true;
  }
  EXPECT_EQ(read.width, result.map.width) << what;
  EXPECT_EQ(read.height, result.map.height) << what;
  EXPECT_EQ(read.coefficients, result.map.coefficients) << what;
  fs::remove(file);
  return true;
}

TEST(CalibrationRoundTrip, EveryImageAndBlockSizeWritesAFileTheNavigationReads) {
  const std::vector<std::pair<int, int>> sizes = {
      {16, 16}, {18, 13}, {40, 24}, {96, 64}, {232, 48}};
  const std::vector<std::pair<int, int>> blocks = {{3, 3}, {15, 7}, {31, 11}};
  std::vector<std::string> calibrated;
  for (const auto& [width, height] : sizes)
    for (const auto& [block_width, block_height] : blocks)
      for (const int max_shift : {2, 8}) {
        CalibrationPairShape shape{width, height, 0, width, 4.0, 1.25, 0.01};
        CalibrationOptions options;
        options.block_width = block_width;
        options.block_height = block_height;
        options.max_shift = max_shift;
        options.max_disparity = 8;
        options.grid_step = 2;
        const std::string what = fmt::format("{}x{} block {}x{} shift {}", width, height,
                                             block_width, block_height, max_shift);
        if (expect_round_trip(render_calibration_pair(shape, 7), options, what))
          calibrated.push_back(what);
      }
  // The pairs with room for the default block and its search are calibrated, not refused.
  for (const char* what : {"96x64 block 15x7 shift 2", "96x64 block 15x7 shift 8",
                           "232x48 block 15x7 shift 2", "232x48 block 15x7 shift 8"})
    EXPECT_NE(std::find(calibrated.begin(), calibrated.end(), what), calibrated.end()) << what;
}

// Matches in a band 80 columns wide at the centre of a wider image, whose true map (a roll of
// 0.05 rows per column) reaches 0.05 x 299.5 = 15, 35 and 100 rows at the edges of images 600,
// 1400 and 4000 wide: the last is more than a calibration may correct and must be refused.
TEST(CalibrationRoundTrip, AMapBeyondWhatACalibrationMayCorrectIsRefusedNotWritten) {
  for (const int width : {600, 1400, 4000}) {
    const int middle = width / 2;
    const CalibrationPairShape shape{width, 40, middle - 40, middle + 40, 6.0, 0.0, 0.05};
    const bool calibrated = expect_round_trip(render_calibration_pair(shape, 11), {},
                                              fmt::format("{} wide, 80 textured", width));
    EXPECT_TRUE(width != 4000 || !calibrated) << width;
  }
  const CalibrationPairShape shape{4000, 40, 1960, 2040, 6.0, 0.0, 0.05};
  const CalibrationPair pair = render_calibration_pair(shape, 11);
  try {
    (void)calibrate_vertical_parallax(pair.left, pair.right);
    ADD_FAILURE() << "calibrated a map of 100 rows";
  } catch (const CalibrationError& error) {
    EXPECT_NE(std::string(error.what()).find("more than the 64 rows a calibration may correct"),
              std::string::npos)
        << error.what();
  }
}

} // namespace
} // namespace marsokhod::nav
