// The pyramid walk handing the original layer on band by band: assembled and finished, it is
// the whole-layer walk's result, with the same work.
#include "nav/stereo_test_support.hpp"

#include "marsokhod/nav/features/layer_features.hpp"
#include "marsokhod/nav/features/pair_pyramid.hpp"
#include "marsokhod/nav/stereo/layered_matching.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace marsokhod::nav {
namespace {

using testing::DotPair;
using testing::DotScene;
using testing::make_dot_pair;

constexpr float kUnknown = std::numeric_limits<float>::infinity();

// The bands as they came, copied into whole images, and how often each row came.
struct AssembledLayer {
  AssembledLayer(int width, int height)
      : disparity(width, height, 1, 0.0F), valid(width, height, 1, 0),
        arrivals(static_cast<std::size_t>(height), 0) {}

  void take(const MatchedBand& band) {
    for (int row = 0; row < band.disparity.height(); ++row) {
      const int y = band.first_row + row;
      ++arrivals.at(static_cast<std::size_t>(y));
      std::copy_n(band.disparity.row(row), band.disparity.width(), disparity.row(y));
      std::copy_n(band.valid.row(row), band.valid.width(), valid.row(y));
    }
    largest_band = std::max(largest_band, band.disparity.height());
  }

  imaging::Image<float> disparity;
  imaging::Image<std::uint8_t> valid;
  std::vector<int> arrivals;
  int largest_band = 0;
};

// match_stereo's walk, with the original layer handed on band by band.
StereoResult banded_walk(const DotPair& pair, const StereoOptions& options, CountingMeter& meter,
                         AssembledLayer& assembled) {
  const MatchedBandSink sink = [&assembled](const MatchedBand& band) { assembled.take(band); };
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
  LayeredMatching matching(pair.left.width(), pair.left.height(), options, memory, &sink);
  const PairPyramid pyramid(pair.left.view(), pair.right.view(), matching.levels(), meter, memory);
  while (!matching.finished()) {
    const int level = matching.next_level();
    const auto left = pyramid.layer(level, imaging::Eye::left);
    const LayerFeatures left_features = layer_features(left, options.feature, meter, memory);
    const LayerFeatures right_features =
        layer_features(pyramid.layer(level, imaging::Eye::right), options.feature, meter, memory);
    matching.match_layer(left, left_features, right_features, meter);
  }
  return matching.take_result();
}

void expect_banded_walk_is_the_whole_walk(const DotPair& pair, const StereoOptions& options) {
  CountingMeter whole_work;
  const StereoResult whole = match_stereo(pair.left.view(), pair.right.view(), options, whole_work);
  CountingMeter banded_work;
  AssembledLayer assembled(pair.left.width(), pair.left.height());
  const StereoResult banded = banded_walk(pair, options, banded_work, assembled);
  EXPECT_TRUE(banded.disparity.empty()) << "the original layer is not kept";
  EXPECT_TRUE(banded.reason.empty());
  for (std::size_t y = 0; y < assembled.arrivals.size(); ++y)
    EXPECT_EQ(assembled.arrivals[y], 1) << "row " << y;
  EXPECT_LT(assembled.largest_band, pair.left.height() / 4) << "bands, not the whole layer";
  finish_original_layer(assembled.disparity, assembled.valid.view(), options, banded_work,
                        std::pmr::get_default_resource());
  EXPECT_EQ(assembled.disparity, whole.disparity);
  EXPECT_EQ(assembled.valid, whole.valid);
  EXPECT_EQ(banded.valid_pixels, whole.valid_pixels);
  ASSERT_EQ(banded.layers.size(), whole.layers.size());
  for (std::size_t i = 0; i < whole.layers.size(); ++i)
    EXPECT_EQ(banded.layers[i].candidates, whole.layers[i].candidates) << "layer " << i;
  for (std::size_t kind = 0; kind < kWorkKinds; ++kind)
    EXPECT_EQ(banded_work.count(static_cast<Work>(kind)), whole_work.count(static_cast<Work>(kind)))
        << to_string(static_cast<Work>(kind));
}

TEST(LayeredMatching, TheOriginalLayerHandedOnBandByBandFinishesIntoTheWholeLayersResult) {
  expect_banded_walk_is_the_whole_walk(make_dot_pair(DotScene{}), testing::dot_scene_options());
}

TEST(LayeredMatching, BandsGoingBottomUpUnderTheGroundPriorAssembleAsWell) {
  // One layer: the original is the top layer, whose ground prior matches the bands bottom-up.
  StereoOptions options = testing::dot_scene_options();
  options.pyramid_levels = 1;
  options.ground_prior = true;
  expect_banded_walk_is_the_whole_walk(make_dot_pair(DotScene{}), options);
}

TEST(LayeredMatching, TheUnfilledPolicyLeavesTheAssembledRejectsUnknown) {
  StereoOptions options = testing::dot_scene_options();
  options.fill = FillPolicy::none;
  const DotPair pair = make_dot_pair(DotScene{});
  expect_banded_walk_is_the_whole_walk(pair, options);
  CountingMeter meter;
  AssembledLayer assembled(pair.left.width(), pair.left.height());
  banded_walk(pair, options, meter, assembled);
  // The square hides a band of background from the right camera: rejected pixels stay +inf.
  std::uint64_t rejected = 0;
  for (int y = 0; y < pair.left.height(); ++y)
    for (int x = 0; x < pair.left.width(); ++x)
      if (assembled.valid(x, y) == 0) {
        ++rejected;
        EXPECT_EQ(assembled.disparity(x, y), kUnknown) << x << "," << y;
      }
  EXPECT_GT(rejected, 0U);
}

} // namespace
} // namespace marsokhod::nav
