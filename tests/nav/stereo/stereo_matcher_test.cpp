// The whole matcher on random-dot stereograms whose disparity is known exactly.
#include "nav/stereo_test_support.hpp"

#include "marsokhod/nav/stereo/stereo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace marsokhod::nav {
namespace {

using testing::DotPair;
using testing::DotScene;
using testing::make_dot_pair;
using testing::share_within;

TEST(StereoMatcher, RecoversARandomDotStereogramWithinOnePixel) {
  const DotPair pair = make_dot_pair(DotScene{});
  const StereoResult result =
      match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options());
  ASSERT_TRUE(result.reason.empty()) << result.reason;
  EXPECT_GT(share_within(result.disparity, pair.disparity, pair.seen, 1.0F), 0.98);
}

TEST(StereoMatcher, StillMatchesWhenTheRightCameraHasAnotherGainAndOffset) {
  const DotPair pair = make_dot_pair(DotScene{});
  // A darker right camera with a raised black level: a * I + b spans 40..193.
  const imaging::Image<std::uint8_t> right = testing::gain_offset(pair.right, 0.6, 40.0);
  const StereoResult result =
      match_stereo(pair.left.view(), right.view(), testing::dot_scene_options());
  EXPECT_GT(share_within(result.disparity, pair.disparity, pair.seen, 1.0F), 0.98);
}

TEST(StereoMatcher, TheLeftRightCheckMarksTheBandTheSquareHidesFromTheRightCamera) {
  const DotScene scene;
  const DotPair pair = make_dot_pair(scene);
  const StereoResult result =
      match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options());
  // The occluded band: foreground - background = 8 columns left of the square, on its rows.
  const int band = scene.foreground - scene.background;
  long occluded = 0;
  long flagged = 0;
  long visible = 0;
  long trusted = 0;
  for (int y = scene.square_y; y < scene.square_y + scene.square_size; ++y)
    for (int x = 0; x < scene.width; ++x) {
      if (x >= scene.square_x - band && x < scene.square_x) {
        ++occluded;
        flagged += result.valid(x, y) == 0 ? 1 : 0;
      } else if (pair.seen(x, y) != 0 && std::abs(x - scene.square_x) > 2 &&
                 std::abs(x - scene.square_x - scene.square_size) > 2) {
        ++visible;
        trusted += result.valid(x, y) != 0 ? 1 : 0;
      }
    }
  EXPECT_GT(static_cast<double>(flagged) / static_cast<double>(occluded), 0.8);
  EXPECT_GT(static_cast<double>(trusted) / static_cast<double>(visible), 0.95);
}

TEST(StereoMatcher, FillGivesTheOccludedBandTheBackgroundAndNoneLeavesItUnknown) {
  const DotScene scene;
  const DotPair pair = make_dot_pair(scene);
  StereoOptions options = testing::dot_scene_options();
  const StereoResult filled = match_stereo(pair.left.view(), pair.right.view(), options);
  options.fill = FillPolicy::none;
  const StereoResult raw = match_stereo(pair.left.view(), pair.right.view(), options);
  const int y = scene.square_y + scene.square_size / 2;
  const int x = scene.square_x - (scene.foreground - scene.background) / 2;
  EXPECT_NEAR(filled.disparity(x, y), scene.background, 1.0);
  ASSERT_EQ(raw.valid(x, y), 0);
  EXPECT_TRUE(std::isinf(raw.disparity(x, y)));
  for (int row = 0; row < scene.height; ++row)
    for (int column = 0; column < scene.width; ++column)
      ASSERT_TRUE(std::isfinite(filled.disparity(column, row)));
}

TEST(StereoMatcher, SameInputsGiveIdenticalResultsWhateverTheMeter) {
  const DotPair pair = make_dot_pair(DotScene{});
  const StereoResult first =
      match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options());
  CountingMeter counting;
  const StereoResult counted =
      match_stereo(pair.left.view(), pair.right.view(), testing::dot_scene_options(), counting);
  EXPECT_EQ(first.disparity, counted.disparity);
  EXPECT_EQ(first.valid, counted.valid);
  EXPECT_GT(counting.count(Work::match_candidate), 0U);
}

TEST(StereoMatcher, TheGroundPriorBoundsTheSearchOfRowsAboveNearerGround) {
  // A ground-like scene: disparity 3 in the upper half, 16 in the lower half.
  DotScene scene;
  scene.width = 160;
  scene.height = 128;
  scene.background = 3;
  scene.foreground = 16;
  scene.square_x = 0;
  scene.square_y = 64;
  scene.square_size = 160;
  const DotPair pair = make_dot_pair(scene);
  StereoOptions options;
  options.max_disparity = 40;
  options.ground_prior = false;
  CountingMeter without;
  const StereoResult free_search =
      match_stereo(pair.left.view(), pair.right.view(), options, without);
  options.ground_prior = true;
  CountingMeter with;
  const StereoResult bounded = match_stereo(pair.left.view(), pair.right.view(), options, with);
  EXPECT_LT(with.count(Work::match_candidate), without.count(Work::match_candidate));
  EXPECT_GT(share_within(bounded.disparity, pair.disparity, pair.seen, 1.0F), 0.98);
  EXPECT_GT(share_within(free_search.disparity, pair.disparity, pair.seen, 1.0F), 0.98);
}

} // namespace
} // namespace marsokhod::nav
