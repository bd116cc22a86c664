// Tests: the stereo rig's geometry against the paper's figures and hand calculations.

#include "support/test_files.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/imaging/rig/rig_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

// Expected values below are worked out by hand from the paper's rig (section 2, fig. 2):
// cameras 1.0 m above the ground over the rover centre, optical axes 10 deg below the horizon,
// f = 12 mm on a 7 mm CCD, baseline 0.50 m. Pixel pitch 7 mm / N, so f = 12 / 7 * N px.

namespace marsokhod::imaging {
namespace {

using test_support::kPi;
constexpr double kHeight = 1.0;
constexpr double kBaseline = 0.5;
constexpr double kPitchDownDeg = 10.0;

double rad(double degrees) {
  return degrees * kPi / 180.0;
}
double focal_px(int side) {
  return 12.0 / 7.0 * side;
}
double centre(int side) {
  return (side - 1) / 2.0;
}

StereoRig paper_rig(int side) {
  RigParameters p;
  p.width_px = side;
  p.height_px = side;
  return StereoRig(p);
}

// Depth along the left optical axis of a level-frame point, level rover: the left camera sits
// at (0, B/2, h) and looks along (cos a, 0, -sin a).
double hand_depth(double x, double z, double pitch_down_deg = kPitchDownDeg) {
  const double a = rad(pitch_down_deg);
  return x * std::cos(a) + (kHeight - z) * std::sin(a);
}

TEST(StereoRig, FocalLengthInPixelsIsFocalOverPixelPitch) {
  EXPECT_NEAR(paper_rig(256).focal_px(), 12.0 / (7.0 / 256.0), 1e-12);
  EXPECT_NEAR(paper_rig(128).focal_px(), 12.0 / (7.0 / 128.0), 1e-12);
  EXPECT_DOUBLE_EQ(paper_rig(256).cx(), 127.5);
}

TEST(StereoRig, VerticalFieldOfViewIsThePapersThirtyTwoDegrees) {
  const double expected = 2.0 * std::atan(3.5 / 12.0) * 180.0 / kPi; // 32.52 deg
  EXPECT_NEAR(paper_rig(256).vertical_fov_deg(), expected, 1e-12);
  EXPECT_NEAR(paper_rig(128).vertical_fov_deg(), expected, 1e-12);
  EXPECT_NEAR(paper_rig(256).vertical_fov_deg(), 32.0, 0.6); // the paper rounds down to 32
  // A 320 x 240 sensor with the same pixel pitch is 7 mm wide and 5.25 mm high.
  RigParameters wide;
  wide.width_px = 320;
  wide.height_px = 240;
  EXPECT_NEAR(StereoRig(wide).vertical_fov_deg(), 2.0 * std::atan(2.625 / 12.0) * 180.0 / kPi,
              1e-12);
}

TEST(StereoRig, GroundBecomesVisibleAboutTwoMetresAhead) {
  // The bottom image edge looks 10 deg + atan(3.5 / 12) = 26.26 deg below the horizon; from
  // 1 m up it meets the ground 1 / tan(26.26 deg) = 2.03 m ahead (fig. 2: "2m").
  const double expected = kHeight / std::tan(rad(kPitchDownDeg) + std::atan(3.5 / 12.0));
  for (int side : {128, 256}) {
    EXPECT_NEAR(paper_rig(side).ground_visible_from_m(), expected, 1e-12);
    EXPECT_NEAR(paper_rig(side).ground_visible_from_m(), 2.0, 0.1);
  }
  RigParameters forward;
  forward.mast_forward_m = 0.3;
  EXPECT_NEAR(StereoRig(forward).ground_visible_from_m(), expected + 0.3, 1e-12);
}

// Ground disparity of row v, level rover. A pixel at y = v - cy below the image centre looks
// along camera direction (x, y, f); in the level frame the camera's y axis is
// (-sin a, 0, -cos a) and its optical axis (cos a, 0, -sin a), so the direction falls by
// y cos a + f sin a per unit of camera depth / f. From height h the ray hits the ground at camera
// depth z = h f / (f sin a + y cos a), and d = f B / z = (B / h) (f sin a + y cos a), whatever
// the column. Rows with f sin a + y cos a <= 0 look at or above the horizon: no ground, d = 0.
TEST(StereoRig, GroundDisparityOfEveryRowFollowsTheRowFormula) {
  const double a = rad(kPitchDownDeg);
  for (int side : {128, 256}) {
    const StereoRig rig = paper_rig(side);
    const double f = focal_px(side);
    int rows_above_horizon = 0;
    for (int v = 0; v < side; ++v) {
      const double fall = f * std::sin(a) + (v - centre(side)) * std::cos(a);
      const double expected = fall > 0.0 ? kBaseline / kHeight * fall : 0.0;
      rows_above_horizon += fall <= 0.0 ? 1 : 0;
      for (double u : {0.0, centre(side), side - 1.0})
        ASSERT_NEAR(rig.ground_disparity(u, v), expected, 1e-9) << side << " px, row " << v;
    }
    // Horizon at cy - f tan a: row 24.8 of 128, row 50.1 of 256.
    EXPECT_EQ(rows_above_horizon, static_cast<int>(std::floor(centre(side) - f * std::tan(a))) + 1);
    EXPECT_NEAR(horizon_row(rig), centre(side) - f * std::tan(a), 1e-9);
  }
}

TEST(StereoRig, GroundDistanceOfARowFollowsItsDepressionAngle) {
  const StereoRig rig = paper_rig(256);
  for (double v : {60.0, 127.5, 200.0, 255.0}) {
    const double depression = rad(kPitchDownDeg) + std::atan((v - 127.5) / focal_px(256));
    EXPECT_NEAR(ground_distance_at_row(rig, v), kHeight / std::tan(depression), 1e-9);
  }
  EXPECT_TRUE(std::isinf(ground_distance_at_row(rig, 10.0)));
}

// The 30 cm stone at 14 m (section 2). Top (14, 0, 0.3) and foot (14, 0, 0) have depths
// 14 cos a + 0.7 sin a and 14 cos a + sin a: nearly equal, so their own disparity difference is
// ~0.03 px at 128 px. The ground seen in the top's row lies on the line from the camera (1 m
// up) through the top: by similar triangles 14 * 1 / (1 - 0.3) = 20 m ahead, depth
// 20 cos a + sin a; the top stands ~2.4 px (128) or ~4.7 px (256) above that ground disparity.
TEST(StereoRig, StoneAtFourteenMetresParallaxMatchesHandGeometry) {
  const double ground_behind = 14.0 * kHeight / (kHeight - 0.3);
  for (int side : {128, 256}) {
    const double fb = focal_px(side) * kBaseline;
    const double top = fb / hand_depth(14.0, 0.3);
    const double foot = fb / hand_depth(14.0, 0.0);
    const double ground = fb / hand_depth(ground_behind, 0.0);
    const ObstacleParallax stone = obstacle_parallax(paper_rig(side), 14.0, 0.3);
    EXPECT_NEAR(stone.top_disparity_px, top, 1e-9);
    EXPECT_NEAR(stone.bottom_disparity_px, foot, 1e-9);
    EXPECT_NEAR(stone.top_minus_bottom_px, top - foot, 1e-9);
    EXPECT_NEAR(stone.ground_behind_distance_m, ground_behind, 1e-9);
    EXPECT_NEAR(stone.ground_behind_disparity_px, ground, 1e-9);
    EXPECT_NEAR(stone.top_minus_ground_px, top - ground, 1e-9);
    // Rows: depression angles atan(0.7 / 14) and atan(1 / 14) seen from an axis 10 deg down.
    const double a = rad(kPitchDownDeg);
    EXPECT_NEAR(stone.top_row, centre(side) + focal_px(side) * std::tan(std::atan(0.05) - a), 1e-9);
    EXPECT_NEAR(stone.bottom_row, centre(side) + focal_px(side) * std::tan(std::atan(1 / 14.0) - a),
                1e-9);
  }
  // The figures quoted in docs/camera.md.
  EXPECT_NEAR(obstacle_parallax(paper_rig(128), 14.0, 0.3).top_minus_bottom_px, 0.029, 0.001);
  EXPECT_NEAR(obstacle_parallax(paper_rig(256), 14.0, 0.3).top_minus_bottom_px, 0.059, 0.001);
  EXPECT_NEAR(obstacle_parallax(paper_rig(128), 14.0, 0.3).top_minus_ground_px, 2.37, 0.01);
  EXPECT_NEAR(obstacle_parallax(paper_rig(256), 14.0, 0.3).top_minus_ground_px, 4.73, 0.01);
}

TEST(StereoRig, PointFromDisparityProjectsBackToItsPixel) {
  const StereoRig rig = paper_rig(256);
  for (const Attitude attitude : {Attitude{}, Attitude{5.0, -4.0}, Attitude{-7.0, 3.0}}) {
    for (double u : {0.0, 100.25, 255.0}) {
      for (double v : {0.0, 140.5, 255.0}) {
        for (double d : {0.5, 11.0, 60.0}) {
          const Eigen::Vector3d point = rig.point_from_disparity(u, v, d, attitude);
          const auto left = rig.project(Eye::left, point, attitude);
          const auto right = rig.project(Eye::right, point, attitude);
          ASSERT_TRUE(left && right);
          EXPECT_NEAR(left->x(), u, 1e-9);
          EXPECT_NEAR(left->y(), v, 1e-9);
          EXPECT_NEAR(right->x(), u - d, 1e-9); // x_right = x_left - d
          EXPECT_NEAR(right->y(), v, 1e-9);
        }
      }
    }
  }
}

TEST(StereoRig, PointsAlongARayProjectToItsPixel) {
  const StereoRig rig = paper_rig(128);
  const Attitude tilted{3.0, 6.0};
  for (Eye eye : {Eye::left, Eye::right}) {
    const Eigen::Vector3d centre_level = rig.camera_to_level(eye, tilted).translation();
    for (double u : {0.0, 64.0, 127.0}) {
      for (double v : {3.0, 90.0}) {
        const Eigen::Vector3d direction = rig.ray(eye, u, v, tilted);
        EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
        for (double distance : {0.7, 9.0, 250.0}) {
          const auto pixel = rig.project(eye, centre_level + distance * direction, tilted);
          ASSERT_TRUE(pixel);
          EXPECT_NEAR(pixel->x(), u, 1e-9);
          EXPECT_NEAR(pixel->y(), v, 1e-9);
        }
        EXPECT_FALSE(rig.project(eye, centre_level - direction, tilted));
      }
    }
  }
}

TEST(StereoRig, DisparityOfAProjectedPointIsFocalTimesBaselineOverDepth) {
  const StereoRig rig = paper_rig(256);
  const double fb = focal_px(256) * kBaseline;
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(5.0, 1.0, 0.2), Eigen::Vector3d(14.0, 0.0, 0.3),
        Eigen::Vector3d(3.0, -0.8, -0.4)}) {
    const auto left = rig.project(Eye::left, point);
    const auto right = rig.project(Eye::right, point);
    ASSERT_TRUE(left && right);
    const double depth = hand_depth(point.x(), point.z());
    EXPECT_NEAR(left->x() - right->x(), fb / depth, 1e-9);
    EXPECT_NEAR(rig.disparity_from_depth(depth), fb / depth, 1e-12);
    EXPECT_NEAR(rig.depth_from_disparity(fb / depth), depth, 1e-12);
    EXPECT_NEAR(left->y(), right->y(), 1e-9);
  }
}

TEST(StereoRig, CameraCentresSitOnTheMast) {
  RigParameters p;
  p.mast_forward_m = 0.4;
  const StereoRig rig(p);
  EXPECT_TRUE(
      rig.camera_to_level(Eye::left).translation().isApprox(Eigen::Vector3d(0.4, 0.25, 1.0)));
  EXPECT_TRUE(
      rig.camera_to_level(Eye::right).translation().isApprox(Eigen::Vector3d(0.4, -0.25, 1.0)));
  // The optical axis is 10 deg below the forward direction, the camera x axis points right.
  const Eigen::Matrix3d axes = rig.camera_to_level(Eye::left).linear();
  EXPECT_TRUE(axes.col(2).isApprox(Eigen::Vector3d(std::cos(rad(10)), 0.0, -std::sin(rad(10)))));
  EXPECT_TRUE(axes.col(0).isApprox(Eigen::Vector3d(0.0, -1.0, 0.0)));
}

// Nose up by p turns the body, mast included, about the ground point under the rover centre:
// the cameras move to height h cos p and h sin p back, and look a - p below the horizon. The
// row formula becomes d(v) = (B / (h cos p)) (f sin(a - p) + y cos(a - p)) and a row meets the
// ground h cos p / tan(a - p + atan(y / f)) - h sin p ahead of the centre.
TEST(StereoRig, PitchingNoseUpMakesTheCamerasLookLessDown) {
  const StereoRig rig = paper_rig(256);
  const double f = focal_px(256);
  for (double pitch : {5.0, -5.0}) {
    const Attitude attitude{pitch, 0.0};
    const double look = rad(kPitchDownDeg - pitch);
    const double height = kHeight * std::cos(rad(pitch));
    for (int v = 0; v < 256; v += 5) {
      const double y = v - 127.5;
      const double fall = f * std::sin(look) + y * std::cos(look);
      const double expected = fall > 0.0 ? kBaseline / height * fall : 0.0;
      ASSERT_NEAR(rig.ground_disparity(60.0, v, attitude), expected, 1e-9) << "row " << v;
      if (fall > 0.0) {
        const double ahead =
            height / std::tan(look + std::atan(y / f)) - kHeight * std::sin(rad(pitch));
        ASSERT_NEAR(ground_distance_at_row(rig, v, attitude), ahead, 1e-12 * ahead + 1e-9)
            << "row " << v;
      }
    }
    EXPECT_NEAR(horizon_row(rig, attitude), 127.5 - f * std::tan(look), 1e-9);
  }
  // Nose up pushes the horizon down the image: row 50.1 level, row 88.1 at +5 deg.
  EXPECT_GT(horizon_row(rig, {5.0, 0.0}), horizon_row(rig));
}

// Roll r about the forward axis. The level "up" vector in body axes is (0, sin r, cos r); in
// camera axes (x = -y_body, y = (-sin a, 0, -cos a), z = (cos a, 0, -sin a)) it is
// (-sin r, -cos a cos r, -sin a cos r). Horizontal rays (x, y, f) are orthogonal to it:
// y = -x tan r / cos a - f tan a, a line at angle -atan(tan r / cos a) in the image (right
// side down lifts the horizon on the right); for a = 0 that is exactly -r.
TEST(StereoRig, RollTurnsTheHorizonLineByTheRollAngle) {
  for (double pitch_down : {kPitchDownDeg, 0.0}) {
    RigParameters p;
    p.pitch_down_deg = pitch_down;
    const StereoRig rig(p);
    for (double roll : {4.0, -4.0, 15.0}) {
      const Attitude attitude{0.0, roll};
      const Eigen::Vector3d centre_level = rig.camera_to_level(Eye::left, attitude).translation();
      const double far = 1e9;
      const auto a =
          rig.project(Eye::left, centre_level + far * Eigen::Vector3d(1.0, 0.2, 0.0), attitude);
      const auto b =
          rig.project(Eye::left, centre_level + far * Eigen::Vector3d(1.0, -0.2, 0.0), attitude);
      ASSERT_TRUE(a && b);
      const double angle = std::atan2(b->y() - a->y(), b->x() - a->x());
      const double expected = -std::atan(std::tan(rad(roll)) / std::cos(rad(pitch_down)));
      EXPECT_NEAR(angle, expected, 1e-9);
      if (pitch_down != 0.0)
        continue;
      EXPECT_NEAR(angle, -rad(roll), 1e-9);
    }
  }
}

// First-order effect of a small right-camera rotation (pan phi about y, tilt w about x, roll k
// about z) on a pixel (x, y) measured from the principal point. The camera turns by R, so a
// direction X = (x, y, f) is seen as R^T X ~ X - theta x X with theta = (w, phi, k):
// X' = (x - phi f + k y, y - k x + w f, f - w y + phi x). Dividing by X'_z / f to first order:
//   dx = -phi (f + x^2 / f) + w x y / f + k y,   dy = w (f + y^2 / f) - phi x y / f - k x,
// the paper's section 2 formula (its signs follow its own axis directions). Tilt dominates dy.
TEST(StereoRig, SmallMisalignmentShiftsTheRightImageAsThePapersFormula) {
  const double f = focal_px(256);
  const double arcsec = kPi / (180.0 * 3600.0);
  const StereoRig ideal = paper_rig(256);
  struct Case {
    Misalignment misalignment;
    double phi, w, k;
  };
  for (const Case& c : {Case{{0.0, 120.0, 0.0}, 0.0, 120.0 * arcsec, 0.0},
                        Case{{120.0, 0.0, 0.0}, 120.0 * arcsec, 0.0, 0.0},
                        Case{{0.0, 0.0, 120.0}, 0.0, 0.0, 120.0 * arcsec}}) {
    RigParameters p;
    p.right_misalignment = c.misalignment;
    const StereoRig rig(p);
    for (const Eigen::Vector3d& point :
         {Eigen::Vector3d(6.0, 0.25, 0.9), Eigen::Vector3d(3.0, 1.5, 0.0),
          Eigen::Vector3d(20.0, -4.0, 0.0)}) {
      const auto seen = ideal.project(Eye::right, point);
      const auto moved = rig.project(Eye::right, point);
      ASSERT_TRUE(seen && moved);
      const double x = seen->x() - 127.5;
      const double y = seen->y() - 127.5;
      const double dx = -c.phi * (f + x * x / f) + c.w * x * y / f + c.k * y;
      const double dy = c.w * (f + y * y / f) - c.phi * x * y / f - c.k * x;
      EXPECT_NEAR(moved->x() - seen->x(), dx, 1e-3);
      EXPECT_NEAR(moved->y() - seen->y(), dy, 1e-3);
      EXPECT_EQ(*rig.project(Eye::left, point), *ideal.project(Eye::left, point));
    }
  }
  // At the image centre the tilt moves rows by f * w: 438.9 px * 120" = 0.255 px.
  RigParameters tilted;
  tilted.right_misalignment.tilt_arcsec = 120.0;
  const Eigen::Vector3d on_axis = StereoRig(tilted).camera_to_level(Eye::right).translation() +
                                  10.0 * ideal.ray(Eye::right, 127.5, 127.5);
  EXPECT_NEAR(StereoRig(tilted).project(Eye::right, on_axis)->y() - 127.5, f * 120.0 * arcsec,
              1e-6);
}

TEST(StereoRig, ZeroOrNegativeDisparityHasNoPoint) {
  const StereoRig rig;
  EXPECT_TRUE(std::isinf(rig.depth_from_disparity(0.0)));
  EXPECT_TRUE(std::isinf(rig.depth_from_disparity(-2.0)));
  EXPECT_THROW(rig.point_from_disparity(10, 10, 0.0), std::domain_error);
  EXPECT_THROW(rig.point_from_disparity(10, 10, -1.0), std::domain_error);
  EXPECT_THROW(rig.point_from_disparity(10, 10, std::nan("")), std::domain_error);
}

TEST(StereoRig, ImpossibleParametersAreRejectedByName) {
  struct Case {
    void (*spoil)(RigParameters&);
    const char* key;
  };
  const Case cases[] = {
      {[](RigParameters& p) { p.baseline_m = -0.5; }, "baseline_m"},
      {[](RigParameters& p) { p.baseline_m = 0.0; }, "baseline_m"},
      {[](RigParameters& p) { p.focal_mm = 0.0; }, "focal_mm"},
      {[](RigParameters& p) { p.sensor_mm = -7.0; }, "sensor_mm"},
      {[](RigParameters& p) { p.mast_height_m = 0.0; }, "mast_height_m"},
      {[](RigParameters& p) { p.pitch_down_deg = 90.0; }, "pitch_down_deg"},
      {[](RigParameters& p) { p.pitch_down_deg = -89.5; }, "pitch_down_deg"},
      {[](RigParameters& p) { p.width_px = 15; }, "width_px"},
      {[](RigParameters& p) { p.height_px = 16385; }, "height_px"},
      {[](RigParameters& p) { p.mast_forward_m = std::nan(""); }, "mast_forward_m"},
      {[](RigParameters& p) { p.right_misalignment.tilt_arcsec = 4000.0; }, "tilt_arcsec"},
  };
  for (const Case& c : cases) {
    RigParameters p;
    c.spoil(p);
    try {
      StereoRig rig(p);
      ADD_FAILURE() << "accepted a bad " << c.key;
    } catch (const RigError& error) {
      EXPECT_NE(std::string(error.what()).find(c.key), std::string::npos) << error.what();
    }
  }
  RigParameters edge;
  edge.width_px = 16;
  edge.height_px = 16384;
  edge.pitch_down_deg = -89.0;
  // Looking 89 deg up, the ground 14 m ahead is in front of a camera 0.2 m above it: the
  // optical axis (cos 89, 0, sin 89) has 14 cos 89 - 0.2 sin 89 = 0.044 m along it.
  edge.mast_height_m = 0.2;
  EXPECT_NO_THROW(StereoRig{edge});
}

TEST(GroundRange, IsTheHorizontalDistanceFromTheRoverCentre) {
  EXPECT_DOUBLE_EQ(ground_range_m(Eigen::Vector3d(3.0, -4.0, 7.0)), 5.0);
}

} // namespace
} // namespace marsokhod::imaging
