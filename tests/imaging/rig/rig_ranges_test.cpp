// Tests: every documented rig value gives finite geometry or a clear error, never NaN.

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/imaging/rig/rig_geometry.hpp"
#include "marsokhod/io/formats/toml_float.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace marsokhod::imaging {
namespace {

namespace fs = std::filesystem;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The ranges as docs/formats.md ("Rig files") states them, written out independently of the
// code's table.
struct DocumentedRange {
  const char* key;
  double low;
  double high;
  void (*set)(RigParameters&, double);
};

const std::vector<DocumentedRange>& documented_ranges() {
  static const std::vector<DocumentedRange> ranges = {
      {"mast_height_m", 0.01, 100.0, [](RigParameters& p, double v) { p.mast_height_m = v; }},
      {"mast_forward_m", -100.0, 100.0, [](RigParameters& p, double v) { p.mast_forward_m = v; }},
      {"pitch_down_deg", -89.0, 89.0, [](RigParameters& p, double v) { p.pitch_down_deg = v; }},
      {"focal_mm", 0.1, 10000.0, [](RigParameters& p, double v) { p.focal_mm = v; }},
      {"sensor_mm", 0.1, 1000.0, [](RigParameters& p, double v) { p.sensor_mm = v; }},
      {"baseline_m", 0.001, 100.0, [](RigParameters& p, double v) { p.baseline_m = v; }},
      {"width_px", 16, 16384, [](RigParameters& p, double v) { p.width_px = static_cast<int>(v); }},
      {"height_px", 16, 16384,
       [](RigParameters& p, double v) { p.height_px = static_cast<int>(v); }},
      {"pan_arcsec", -3600.0, 3600.0,
       [](RigParameters& p, double v) { p.right_misalignment.pan_arcsec = v; }},
      {"tilt_arcsec", -3600.0, 3600.0,
       [](RigParameters& p, double v) { p.right_misalignment.tilt_arcsec = v; }},
      {"roll_arcsec", -3600.0, 3600.0,
       [](RigParameters& p, double v) { p.right_misalignment.roll_arcsec = v; }},
  };
  return ranges;
}

bool is_integer_key(const DocumentedRange& range) {
  return std::string(range.key).ends_with("_px");
}

// The range's ends and the values just inside them.
std::vector<double> legal_values(const DocumentedRange& range) {
  if (is_integer_key(range))
    return {range.low, range.low + 1, range.high - 1, range.high};
  return {range.low, std::nextafter(range.low, kInfinity), std::nextafter(range.high, -kInfinity),
          range.high};
}

std::vector<double> illegal_values(const DocumentedRange& range) {
  if (is_integer_key(range))
    return {range.low - 1, range.high + 1};
  return {std::nextafter(range.low, -kInfinity),
          std::nextafter(range.high, kInfinity),
          std::nan(""),
          kInfinity,
          -kInfinity,
          1e308};
}

// Every figure a consumer of the rig computes: `marsokhod rig` (its table and the paper's
// stone), the renderer (rays, projections) and `nav --rig` (triangulation). Only the figures
// documented as possibly infinite (ground never reached) may be +inf; nothing may be NaN.
void expect_finite_geometry(const StereoRig& rig, const std::string& label) {
  EXPECT_TRUE(std::isfinite(rig.focal_px())) << label;
  EXPECT_GT(rig.focal_px(), 0.0) << label;
  EXPECT_TRUE(std::isfinite(rig.vertical_fov_deg())) << label;
  const double visible = rig.ground_visible_from_m();
  EXPECT_TRUE(std::isfinite(visible) || visible == kInfinity) << label;
  EXPECT_TRUE(std::isfinite(horizon_row(rig))) << label;
  std::vector<double> rows;
  for (int v = 0; v < rig.height(); v += 16)
    rows.push_back(v);
  rows.push_back(rig.height() - 1);
  for (const double v : rows) {
    const double distance = ground_distance_at_row(rig, v);
    EXPECT_TRUE(std::isfinite(distance) || distance == kInfinity) << label << " row " << v;
    const double disparity = rig.ground_disparity(rig.cx(), v);
    EXPECT_TRUE(std::isfinite(disparity)) << label << " row " << v;
    EXPECT_GE(disparity, 0.0) << label << " row " << v;
  }
  const ObstacleParallax stone = obstacle_parallax(rig, 14.0, 0.3);
  for (const double figure :
       {stone.top_row, stone.bottom_row, stone.top_disparity_px, stone.bottom_disparity_px,
        stone.top_minus_bottom_px, stone.ground_behind_disparity_px, stone.top_minus_ground_px})
    EXPECT_TRUE(std::isfinite(figure)) << label;
  EXPECT_FALSE(std::isnan(stone.ground_behind_distance_m)) << label;
  const double right = rig.width() - 1.0;
  const double bottom = rig.height() - 1.0;
  for (const Eye eye : {Eye::left, Eye::right})
    for (const double u : {0.0, right})
      for (const double v : {0.0, bottom}) {
        EXPECT_TRUE(rig.ray(eye, u, v).allFinite()) << label;
        EXPECT_TRUE(rig.point_from_disparity(u, v, 1.0).allFinite()) << label;
      }
  const auto seen = rig.project(Eye::right, Eigen::Vector3d(14.0, 0.0, 0.0));
  EXPECT_TRUE(!seen || seen->allFinite()) << label;
}

// A legal value either gives finite geometry or is refused because the cameras would not see
// the ground ahead; it is never refused as out of range.
void expect_legal(const RigParameters& p, const std::string& label) {
  try {
    const StereoRig rig(p);
    expect_finite_geometry(rig, label);
  } catch (const RigError& error) {
    EXPECT_NE(std::string(error.what()).find("the cameras do not see the ground ahead"),
              std::string::npos)
        << label << ": " << error.what();
  }
}

TEST(RigRanges, EveryFieldOverItsDocumentedRangeGivesFiniteGeometry) {
  for (const DocumentedRange& range : documented_ranges())
    for (const double value : legal_values(range)) {
      RigParameters p;
      range.set(p, value);
      expect_legal(p, std::string(range.key) + " = " + std::to_string(value));
    }
}

TEST(RigRanges, ValuesJustOutsideTheDocumentedRangeAreRefusedByName) {
  for (const DocumentedRange& range : documented_ranges())
    for (const double value : illegal_values(range)) {
      if (is_integer_key(range) && !std::isfinite(value))
        continue;
      if (is_integer_key(range) && std::abs(value) > 1e9)
        continue;
      RigParameters p;
      range.set(p, value);
      try {
        const StereoRig rig(p);
        ADD_FAILURE() << "accepted " << range.key << " = " << value;
      } catch (const RigError& error) {
        EXPECT_NE(std::string(error.what()).find(range.key), std::string::npos) << error.what();
      }
    }
}

// Corners of the box of legal lengths, lens and pitch together: the bounds hold jointly, not
// only one field at a time.
TEST(RigRanges, EveryCornerOfTheLegalRangesGivesFiniteGeometryOrTheGroundError) {
  for (int corner = 0; corner < 32; ++corner)
    for (const double pitch : {-89.0, 0.0, 89.0})
      for (const int size : {16, 16384}) {
        RigParameters p;
        p.mast_height_m = corner & 1 ? 100.0 : 0.01;
        p.mast_forward_m = corner & 2 ? 100.0 : -100.0;
        p.focal_mm = corner & 4 ? 10000.0 : 0.1;
        p.sensor_mm = corner & 8 ? 1000.0 : 0.1;
        p.baseline_m = corner & 16 ? 100.0 : 0.001;
        p.pitch_down_deg = pitch;
        p.width_px = size;
        p.height_px = 16400 - size;
        p.right_misalignment = {3600.0, -3600.0, 3600.0};
        expect_legal(p, "corner " + std::to_string(corner) + " pitch " + std::to_string(pitch) +
                            " size " + std::to_string(size));
      }
}

// The ground point 14 m ahead is behind the image plane when the optical axis (cos a, 0, -sin a)
// has a non-positive component along the offset (14 - forward, 0, -height): a camera 1 m up
// looking 89 deg up has 14 cos 89 - 1 sin 89 = -0.76 m.
TEST(RigRanges, CamerasLookingAwayFromTheGroundAheadAreRefusedWithTheReason) {
  RigParameters up;
  up.pitch_down_deg = -89.0;
  EXPECT_THROW(StereoRig{up}, RigError);
  // Looking 80 deg up from 1 m: 14 cos 80 - sin 80 = 1.45 m in front: accepted.
  up.pitch_down_deg = -80.0;
  EXPECT_NO_THROW(StereoRig{up});
  // Cameras 20 m ahead of the rover centre on a 100 m boom: the stone 14 m ahead is behind.
  RigParameters ahead;
  ahead.mast_forward_m = 20.0;
  try {
    const StereoRig rig(ahead);
    ADD_FAILURE() << "accepted a rig ahead of the stone";
  } catch (const RigError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the cameras do not see the ground ahead"), std::string::npos);
    EXPECT_NE(message.find("rig.mast_forward_m = 20"), std::string::npos) << message;
  }
}

fs::path write_ranges_rig(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "marsokhod-rig-ranges-test";
  fs::create_directories(dir);
  const fs::path path = dir / (name + ".toml");
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string ranges_load_error(const fs::path& path) {
  try {
    StereoRig::load(path);
  } catch (const RigFileError& error) {
    return error.what();
  }
  return "";
}

// A value as a rig file spells it: an integer for the sizes, the shortest float otherwise.
std::string file_value(const DocumentedRange& range, double value) {
  if (is_integer_key(range))
    return std::to_string(static_cast<long long>(value));
  return io::toml_float(value);
}

std::string rig_file_text(const DocumentedRange& range, const std::string& value) {
  const bool misalignment = std::string(range.key).ends_with("_arcsec");
  return fmt::format("{}\n{} = {}\n", misalignment ? "[rig.right_misalignment]" : "[rig]",
                     range.key, value);
}

// The file reader applies the constructor's ranges: the ends are read (or the rig is refused
// only because its cameras do not see the ground), and a finite value just outside is refused
// at its line and key in io::TomlTable's words.
TEST(RigRanges, RigFilesHaveTheDocumentedRanges) {
  for (const DocumentedRange& range : documented_ranges()) {
    const bool misalignment = std::string(range.key).ends_with("_arcsec");
    const std::string key =
        std::string(misalignment ? "rig.right_misalignment." : "rig.") + range.key;
    for (const double value : legal_values(range)) {
      const fs::path path =
          write_ranges_rig("legal", rig_file_text(range, file_value(range, value)));
      const std::string message = ranges_load_error(path);
      EXPECT_TRUE(message.empty() || message.find("do not see the ground") != std::string::npos)
          << key << " = " << value << ": " << message;
    }
    for (const double value : illegal_values(range)) {
      if (!std::isfinite(value) || (is_integer_key(range) && std::abs(value) > 1e9))
        continue;
      const fs::path path =
          write_ranges_rig("illegal", rig_file_text(range, file_value(range, value)));
      const std::string message = ranges_load_error(path);
      EXPECT_EQ(
          message.rfind(fmt::format("{}:2: '{}': {} is out of range: it must be {}", path.string(),
                                    key, value, io::range_text(range.low, range.high)),
                        0),
          0U)
          << message;
    }
  }
}

// The examples: each is now an error naming the file (and the key where one is to
// blame) instead of an internal message halfway through the output or -nan.
TEST(RigRanges, TheReportedRigFilesAreRefusedNamingTheFile) {
  // Each value is in range; the rig as a whole is refused at its [rig] table.
  const fs::path up = write_ranges_rig("up", "[rig]\npitch_down_deg = -89\n");
  EXPECT_EQ(ranges_load_error(up),
            up.string() + ":1: the cameras do not see the ground ahead at this pitch and mast "
                          "position: the paper's 30 cm stone 14 m ahead of the rover centre would "
                          "be behind the left camera (rig.pitch_down_deg = -89, rig.mast_height_m "
                          "= 1, rig.mast_forward_m = 0)");

  const fs::path far = write_ranges_rig("far", "[rig]\nmast_forward_m = 1e6\n");
  EXPECT_EQ(
      ranges_load_error(far),
      far.string() +
          ":2: 'rig.mast_forward_m': 1000000 is out of range: it must be between -100 and 100");

  const fs::path wide = write_ranges_rig("wide", "[rig]\nbaseline_m = 1e308\n");
  EXPECT_EQ(ranges_load_error(wide),
            wide.string() +
                ":2: 'rig.baseline_m': 1e+308 is out of range: it must be between 0.001 and 100");
}

} // namespace
} // namespace marsokhod::imaging
