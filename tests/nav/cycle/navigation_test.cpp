// Tests: one navigation cycle end to end, the texture mask and the rover's disparity range.

#include "nav/paper_rig.hpp"

#include "marsokhod/nav/cycle/navigation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>

// The whole chain on pairs made here: a textured level ground seen by the paper's rig, whose
// right image is the left one shifted row by row by the ground disparity written out by hand.

namespace marsokhod::nav {
namespace {

constexpr int kSide = 128;

using test_rigs::rig_of_side;

// d(v) = (B / h) (f sin a + (v - cy) cos a), 0 above the horizon (docs/camera.md).
double ground_disparity(const imaging::StereoRig& rig, int v) {
  const double a = 10.0 * 3.141592653589793 / 180.0;
  return std::max(0.0, 0.5 * (rig.focal_px() * std::sin(a) + (v - rig.cy()) * std::cos(a)));
}

// Texture fixed to the ground: a function of the ground point, sampled through the left and
// the right camera, so both views agree wherever the ground is seen.
double texture(double forward, double left) {
  const auto cell = [](double value, double size) {
    return static_cast<long>(std::floor(value / size));
  };
  std::uint64_t h = static_cast<std::uint64_t>(cell(forward, 0.05) * 73856093L) ^
                    static_cast<std::uint64_t>(cell(left, 0.05) * 19349663L);
  h = (h ^ (h >> 29)) * 0xbf58476d1ce4e5b9ULL;
  return 60.0 + static_cast<double>((h >> 40) % 140);
}

struct Pair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
};

// Each camera's pixel looks along its ray to the ground plane z = 0 (sky grey above it).
Pair ground_pair(const imaging::StereoRig& rig) {
  Pair pair{imaging::Image<std::uint8_t>(rig.width(), rig.height()),
            imaging::Image<std::uint8_t>(rig.width(), rig.height())};
  for (const imaging::Eye eye : {imaging::Eye::left, imaging::Eye::right}) {
    imaging::Image<std::uint8_t>& image = eye == imaging::Eye::left ? pair.left : pair.right;
    const Eigen::Vector3d origin = rig.camera_to_level(eye).translation();
    for (int v = 0; v < rig.height(); ++v)
      for (int u = 0; u < rig.width(); ++u) {
        const Eigen::Vector3d ray = rig.ray(eye, u, v);
        if (ray.z() >= -1e-6) {
          image(u, v) = 200;
          continue;
        }
        const Eigen::Vector3d ground = origin + (-origin.z() / ray.z()) * ray;
        image(u, v) = static_cast<std::uint8_t>(texture(ground.x(), ground.y()));
      }
  }
  return pair;
}

TEST(Navigate, LevelTexturedGroundGivesAStraightPathAhead) {
  const imaging::StereoRig rig = rig_of_side(kSide);
  const Pair pair = ground_pair(rig);
  // At 128 px the ground 10 m away is a few rows; a 5-7 m destination keeps the test about the
  // chain rather than about matching the far field.
  NavigationOptions options;
  options.planner.target_min_m = 5.0;
  options.planner.target_max_m = 7.0;
  const NavigationResult result = navigate(pair.left, pair.right, rig, options);
  ASSERT_TRUE(result.found()) << result.reason();
  // In the lower half, where the right camera sees the ground too (x > d), the matched
  // disparity follows the hand formula and the ground is traversable.
  int close = 0;
  int open = 0;
  int counted = 0;
  for (int v = kSide / 2; v < kSide; v += 2)
    for (int u = static_cast<int>(1.2 * ground_disparity(rig, v)) + 2; u < kSide - 2; u += 2) {
      ++counted;
      close += std::abs(result.stereo.disparity(u, v) - ground_disparity(rig, v)) <= 1.0 ? 1 : 0;
      open += result.zones.traversable(u, v) ? 1 : 0;
    }
  EXPECT_GT(close, counted * 9 / 10);
  EXPECT_GT(open, counted * 9 / 10);
  EXPECT_GE(result.drive.target_m, 5.0);
  EXPECT_LE(result.drive.target_m, 7.0);
  EXPECT_LT(result.drive.start_m, 2.5);
  for (const DriveCommand& c : result.drive.commands)
    EXPECT_LT(std::abs(c.turn_deg), 10.0);
}

TEST(Navigate, UniformImagesGiveNoPathAndSayWhy) {
  const imaging::StereoRig rig = rig_of_side(kSide);
  for (const std::uint8_t grey : {std::uint8_t{0}, std::uint8_t{255}}) {
    const imaging::Image<std::uint8_t> flat(kSide, kSide, 1, grey);
    const NavigationResult result = navigate(flat, flat, rig, NavigationOptions{});
    EXPECT_FALSE(result.found()) << int{grey};
    EXPECT_FALSE(result.reason().empty()) << int{grey};
    EXPECT_TRUE(result.plan.pixels.empty());
  }
}

TEST(Navigate, RejectsPairsThatDoNotFitEachOtherOrTheRig) {
  const imaging::StereoRig rig = rig_of_side(kSide);
  const imaging::Image<std::uint8_t> image(kSide, kSide, 1, 90);
  const imaging::Image<std::uint8_t> narrower(kSide - 2, kSide, 1, 90);
  EXPECT_THROW(navigate(image, narrower, rig, NavigationOptions{}), std::invalid_argument);
  const imaging::StereoRig other = rig_of_side(64);
  EXPECT_THROW(navigate(image, image, other, NavigationOptions{}), std::invalid_argument);
  // 16 px halved twice is 4 px, too small for 3x3 windows with context.
  const imaging::StereoRig small_rig = rig_of_side(16);
  const imaging::Image<std::uint8_t> small(16, 16, 1, 90);
  NavigationOptions three_layers;
  three_layers.stereo.pyramid_levels = 3;
  EXPECT_THROW(navigate(small, small, small_rig, three_layers), std::invalid_argument);
}

TEST(NavigateDisparity, GroundTruthDisparityOfLevelGroundIsTraversable) {
  const imaging::StereoRig rig = rig_of_side(kSide);
  imaging::Image<float> disparity(kSide, kSide, 1, std::numeric_limits<float>::infinity());
  for (int v = 0; v < kSide; ++v)
    for (int u = 0; u < kSide; ++u)
      if (ground_disparity(rig, v) > 0.0)
        disparity(u, v) = static_cast<float>(ground_disparity(rig, v));
  CountingMeter meter;
  const NavigationResult result =
      navigate_disparity(disparity, {}, rig, NavigationOptions{}, meter);
  ASSERT_TRUE(result.found()) << result.reason();
  EXPECT_TRUE(result.stereo.disparity.empty());
  EXPECT_EQ(result.zones.count(Zone::step) + result.zones.count(Zone::slope), 0U);
  EXPECT_EQ(meter.count(Work::match_candidate), 0U);
  EXPECT_GT(meter.count(Work::path_relaxation), 0U);
  EXPECT_EQ(meter.count(Work::range_pixel), result.terrain.known_pixels);
}

TEST(TexturedPixels, MarksWhereTheFiveByFiveNeighbourhoodSpansTheGreyRange) {
  // Against the definition written out pixel by pixel (clamped at the borders), on random
  // images from narrower than the window to wider than a vector.
  std::mt19937 random(5);
  for (const int width : {1, 2, 3, 4, 5, 6, 17, 40}) {
    const int height = 1 + static_cast<int>(random() % 9);
    imaging::Image<std::uint8_t> image(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        image(x, y) = static_cast<std::uint8_t>(100 + random() % 9);
    const imaging::Image<std::uint8_t> textured = textured_pixels(image, 6);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        int hi = 0;
        int lo = 255;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int v =
                image(std::clamp(x + dx, 0, width - 1), std::clamp(y + dy, 0, height - 1));
            hi = std::max(hi, v);
            lo = std::min(lo, v);
          }
        ASSERT_EQ(textured(x, y), hi - lo >= 6 ? 255 : 0)
            << width << "x" << height << " at " << x << "," << y;
      }
  }
}

TEST(RoverMaxDisparity, CoversTheNearestGroundPlusRocks) {
  const imaging::StereoRig rig = rig_of_side(256);
  // Bottom row of the 256 px rig sees level ground with d = 100.88 px (docs/camera.md).
  EXPECT_EQ(rover_max_disparity(rig, {}), static_cast<int>(std::ceil(1.25 * 100.88)));
  EXPECT_LE(rover_max_disparity(rig_of_side(64), imaging::Attitude{-20.0, 0.0}), 63);
}

} // namespace
} // namespace marsokhod::nav
