// Tests: range and elevation from disparity, with the rover pitched, rolled and level.

#include "nav/paper_rig.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav/terrain/elevation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

// Expected values are hand geometry of the paper's rig (section 2): cameras 1.0 m above the
// ground over the rover centre, optical axes 10 deg below the horizon, f = 12/7 N px, baseline
// 0.5 m, left camera 0.25 m left of the centre line. Odd image sides put a pixel centre on the
// principal point, so the optical axis is a pixel.

namespace marsokhod::nav {
namespace {

using test_support::kPi;
constexpr double kHeight = 1.0;
constexpr double kBaseline = 0.5;
using test_support::kInfinity;

double rad(double degrees) {
  return degrees * kPi / 180.0;
}

using test_rigs::rig_of_side;

// The disparity of the level ground at row v of a level rover: a ray y = v - cy pixels below
// the image centre falls by f sin a + y cos a per unit of depth / f, so from height h it meets
// the ground at depth z = h f / (f sin a + y cos a) and d = f B / z.
double hand_ground_disparity(double f, double y_from_centre) {
  const double a = rad(10.0);
  return kBaseline / kHeight * (f * std::sin(a) + y_from_centre * std::cos(a));
}

imaging::Image<float> ground_disparity_map(const imaging::StereoRig& rig) {
  imaging::Image<float> disparity(rig.width(), rig.height(), 1,
                                  std::numeric_limits<float>::infinity());
  for (int v = 0; v < rig.height(); ++v) {
    const double d = hand_ground_disparity(rig.focal_px(), v - rig.cy());
    for (int u = 0; u < rig.width(); ++u)
      if (d > 0.0)
        disparity(u, v) = static_cast<float>(d);
  }
  return disparity;
}

TEST(ReconstructTerrain, OpticalAxisPixelLiesAlongThePitchedAxis) {
  const imaging::StereoRig rig = rig_of_side(129);
  imaging::Image<float> disparity(129, 129, 1, std::numeric_limits<float>::infinity());
  const double d = 20.0;
  disparity(64, 64) = static_cast<float>(d);
  const TerrainPoints terrain = reconstruct_terrain(disparity, rig, {});
  const double depth = rig.focal_px() * kBaseline / d;
  const double a = rad(10.0);
  EXPECT_NEAR(terrain.forward(64, 64), depth * std::cos(a), 1e-4);
  EXPECT_NEAR(terrain.left(64, 64), kBaseline / 2.0, 1e-5);
  EXPECT_NEAR(terrain.elevation(64, 64), kHeight - depth * std::sin(a), 1e-4);
  EXPECT_NEAR(terrain.range(64, 64), std::hypot(depth * std::cos(a), kBaseline / 2.0), 1e-4);
  EXPECT_EQ(terrain.known_pixels, 1U);
}

TEST(ReconstructTerrain, RoverPitchTurnsMastAndAxisTogether) {
  // Nose up by p: the camera sits at (-h sin p, B/2, h cos p) and its axis is a - p below the
  // horizon.
  const imaging::StereoRig rig = rig_of_side(129);
  imaging::Image<float> disparity(129, 129, 1, std::numeric_limits<float>::infinity());
  disparity(64, 64) = 25.0F;
  const double p = rad(4.0);
  const double tilt = rad(10.0) - p;
  const double depth = rig.focal_px() * kBaseline / 25.0;
  const TerrainPoints terrain = reconstruct_terrain(disparity, rig, imaging::Attitude{4.0, 0.0});
  EXPECT_NEAR(terrain.forward(64, 64), -kHeight * std::sin(p) + depth * std::cos(tilt), 1e-4);
  EXPECT_NEAR(terrain.elevation(64, 64), kHeight * std::cos(p) - depth * std::sin(tilt), 1e-4);
  EXPECT_NEAR(terrain.left(64, 64), kBaseline / 2.0, 1e-5);
}

TEST(ReconstructTerrain, RoverRollTurnsMastAboutTheForwardAxis) {
  // Roll r (right side down) is a right-hand turn about x: (x, y, z) -> (x, y cos r - z sin r,
  // y sin r + z cos r). Camera (0, B/2, h); axis (cos a, 0, -sin a).
  const imaging::StereoRig rig = rig_of_side(129);
  imaging::Image<float> disparity(129, 129, 1, std::numeric_limits<float>::infinity());
  disparity(64, 64) = 25.0F;
  const double r = rad(-6.0);
  const double a = rad(10.0);
  const double depth = rig.focal_px() * kBaseline / 25.0;
  const double cam_y = 0.25 * std::cos(r) - kHeight * std::sin(r);
  const double cam_z = 0.25 * std::sin(r) + kHeight * std::cos(r);
  const TerrainPoints terrain = reconstruct_terrain(disparity, rig, imaging::Attitude{0.0, -6.0});
  EXPECT_NEAR(terrain.forward(64, 64), depth * std::cos(a), 1e-4);
  EXPECT_NEAR(terrain.left(64, 64), cam_y + depth * std::sin(a) * std::sin(r), 1e-4);
  EXPECT_NEAR(terrain.elevation(64, 64), cam_z - depth * std::sin(a) * std::cos(r), 1e-4);
}

TEST(ReconstructTerrain, LevelGroundHasZeroElevationAndTheDocumentedRowRanges) {
  const imaging::StereoRig rig = rig_of_side(256);
  const TerrainPoints terrain = reconstruct_terrain(ground_disparity_map(rig), rig, {});
  for (int v = 60; v < 256; v += 13)
    for (int u = 0; u < 256; u += 17)
      ASSERT_NEAR(terrain.elevation(u, v), 0.0, 1e-4) << u << "," << v;
  // Ground straight ahead of the camera column at rows 128 and 255: h / tan(a + atan(y / f)).
  for (const int v : {128, 255}) {
    const double ahead = kHeight / std::tan(rad(10.0) + std::atan((v - 127.5) / rig.focal_px()));
    // The centre column sees the point 0.25 m left of the rover centre line.
    EXPECT_NEAR(terrain.range(127, v), std::hypot(ahead, 0.25), 0.01) << v;
  }
  EXPECT_NEAR(terrain.range(127, 128), 5.63, 0.02); // docs/camera.md table
  EXPECT_NEAR(terrain.range(127, 255), 2.05, 0.02);
}

TEST(ReconstructTerrain, UnusableDisparitiesAreUnknownEverywhere) {
  const imaging::StereoRig rig = rig_of_side(33);
  imaging::Image<float> disparity(33, 33, 1, 10.0F);
  disparity(1, 1) = std::numeric_limits<float>::infinity();
  disparity(2, 1) = std::numeric_limits<float>::quiet_NaN();
  disparity(3, 1) = 0.0F;
  disparity(4, 1) = -3.0F;
  const TerrainPoints terrain = reconstruct_terrain(disparity, rig, {});
  for (int u = 1; u <= 4; ++u) {
    EXPECT_FALSE(terrain.known(u, 1)) << u;
    EXPECT_EQ(terrain.range(u, 1), kInfinity);
    EXPECT_EQ(terrain.forward(u, 1), kInfinity);
    EXPECT_EQ(terrain.left(u, 1), kInfinity);
  }
  EXPECT_TRUE(terrain.known(5, 1));
  EXPECT_EQ(terrain.known_pixels, 33U * 33U - 4U);
}

TEST(ReconstructTerrain, ReportsOneRangeAndOneElevationPerConvertedPixel) {
  const imaging::StereoRig rig = rig_of_side(64);
  imaging::Image<float> disparity(64, 64, 1, std::numeric_limits<float>::infinity());
  for (int v = 0; v < 64; ++v)
    for (int u = 0; u < v; ++u) // a triangle: 0 + 1 + ... + 63 = 2016 pixels
      disparity(u, v) = 12.0F;
  CountingMeter meter;
  reconstruct_terrain(disparity, rig, {}, meter);
  EXPECT_EQ(meter.count(Work::range_pixel), 2016U);
  EXPECT_EQ(meter.count(Work::elevation_pixel), 2016U);
}

TEST(ReconstructTerrain, RejectsADisparityMapOfAnotherSize) {
  const imaging::StereoRig rig = rig_of_side(64);
  const imaging::Image<float> disparity(64, 63, 1, 1.0F);
  EXPECT_THROW(reconstruct_terrain(disparity, rig, {}), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
