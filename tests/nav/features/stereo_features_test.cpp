// Tests: brightness features (census, rank) and the image pyramid's halving.
// Brightness features: unchanged by gain and offset differences between the cameras, and the
// census bits as defined (worked out by hand on small patches).
#include "nav/stereo_test_support.hpp"

#include "marsokhod/nav/features/brightness_features.hpp"
#include "marsokhod/nav/features/image_pyramid.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace marsokhod::nav {
namespace {

imaging::Image<std::uint8_t> patch(int width, int height, std::initializer_list<int> values) {
  imaging::Image<std::uint8_t> image(width, height);
  std::size_t i = 0;
  for (int value : values)
    image.data()[i++] = static_cast<std::uint8_t>(value);
  return image;
}

TEST(BrightnessFeatures, Census3x3SetsOneBitPerDarkerNeighbourInRasterOrder) {
  // Centre 50; neighbours in raster order 10, 90, 50, 20, (centre), 60, 40, 50, 99:
  // darker are 10, 20, 40 -> bits 1 0 0 1 0 1 0 0 (first neighbour most significant).
  const imaging::Image<std::uint8_t> image = patch(3, 3, {10, 90, 50, 20, 50, 60, 40, 50, 99});
  const imaging::Image<std::uint32_t> census =
      brightness_features(image.view(), FeatureKind::census3x3);
  EXPECT_EQ(census(1, 1), 0b10010100U);
}

TEST(BrightnessFeatures, BordersRepeatTheNearestPixel) {
  // Image 50 10 / 90 30. Around the top-left pixel, outside positions repeat the nearest
  // pixel: in raster order 50 50 10 | 50 (c) 10 | 90 90 30 -> darker than 50: 0 0 1 0 1 0 0 1.
  const imaging::Image<std::uint8_t> image = patch(2, 2, {50, 10, 90, 30});
  const imaging::Image<std::uint32_t> census =
      brightness_features(image.view(), FeatureKind::census3x3);
  EXPECT_EQ(census(0, 0), 0b00101001U);
}

TEST(BrightnessFeatures, RankCountsTheDarkerPixelsOfTheFiveByFiveWindow) {
  // A ramp 0..24 in raster order: the centre (12) has exactly 12 darker pixels.
  imaging::Image<std::uint8_t> image(5, 5);
  for (int i = 0; i < 25; ++i)
    image.data()[i] = static_cast<std::uint8_t>(i * 10);
  EXPECT_EQ(brightness_features(image.view(), FeatureKind::rank5x5)(2, 2), 12U);
  const imaging::Image<std::uint32_t> census =
      brightness_features(image.view(), FeatureKind::census5x5);
  // The 12 pixels before the centre are darker: the 12 most significant of 24 bits.
  EXPECT_EQ(census(2, 2), 0xFFF000U);
}

class GainOffsetInvariance : public ::testing::TestWithParam<FeatureKind> {};

TEST_P(GainOffsetInvariance, FeaturesOfAGainAndOffsetImageEqualThoseOfTheImage) {
  // Keep a * I + b inside 0..255 so nothing clips: I in 0..99, a = 1.5, b = 30 -> 30..179.
  imaging::Image<std::uint8_t> image = testing::random_dots(40, 30, 11);
  for (std::size_t i = 0; i < image.size(); ++i)
    image.data()[i] = static_cast<std::uint8_t>(image.data()[i] % 100);
  const imaging::Image<std::uint8_t> brighter = testing::gain_offset(image, 1.5, 30.0);
  const imaging::Image<std::uint8_t> shifted = testing::gain_offset(image, 1.0, 120.0);
  const FeatureKind kind = GetParam();
  const imaging::Image<std::uint32_t> reference = brightness_features(image.view(), kind);
  EXPECT_EQ(brightness_features(brighter.view(), kind), reference);
  EXPECT_EQ(brightness_features(shifted.view(), kind), reference);
}

INSTANTIATE_TEST_SUITE_P(EveryFeature, GainOffsetInvariance,
                         ::testing::Values(FeatureKind::census3x3, FeatureKind::census5x5,
                                           FeatureKind::rank5x5));

TEST(BrightnessFeatures, DistancesAreHammingForCensusAndAbsoluteForRank) {
  EXPECT_EQ(feature_distance(FeatureKind::census3x3, 0b1011U, 0b0110U), 3);
  EXPECT_EQ(feature_distance(FeatureKind::census5x5, 0xFFFFFFU, 0U), 24);
  EXPECT_EQ(feature_distance(FeatureKind::rank5x5, 3U, 17U), 14);
}

TEST(BrightnessFeatures, KindsReadBackFromTheirNames) {
  for (FeatureKind kind : {FeatureKind::census3x3, FeatureKind::census5x5, FeatureKind::rank5x5})
    EXPECT_EQ(parse_feature_kind(to_string(kind)), kind);
  EXPECT_FALSE(parse_feature_kind("sobel").has_value());
}

TEST(ImagePyramid, EachLayerHalvesThePreviousWithRoundedBlockMeans) {
  // 5 x 3: the odd last column and row are dropped; blocks (0,1,4,5 -> 2.5 -> 3) etc.
  const imaging::Image<std::uint8_t> image =
      patch(5, 3, {0, 1, 10, 30, 200, 4, 5, 20, 40, 200, 9, 9, 9, 9, 9});
  const imaging::Image<std::uint8_t> half = halve_image(image.view());
  ASSERT_EQ(half.width(), 2);
  ASSERT_EQ(half.height(), 1);
  EXPECT_EQ(half(0, 0), 3);  // (0 + 1 + 4 + 5) / 4 = 2.5, rounded up
  EXPECT_EQ(half(1, 0), 25); // (10 + 30 + 20 + 40) / 4 = 25
}

TEST(ImagePyramid, HalvingAConstantImageKeepsItsGreyLevel) {
  const imaging::Image<std::uint8_t> image(64, 48, 1, 77);
  const imaging::Image<std::uint8_t> half = halve_image(image.view());
  EXPECT_EQ(half, imaging::Image<std::uint8_t>(32, 24, 1, 77));
}

} // namespace
} // namespace marsokhod::nav
