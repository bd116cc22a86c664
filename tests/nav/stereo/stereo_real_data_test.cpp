// Tests: the stereo matcher's acceptance figures on the real pairs of the shared data.
// The acceptance figures on the real pairs of MARSOKHOD_SHARED_DATA/stereo: bad-1.0 below
// OpenCV StereoBM on every pair and a mean no higher than StereoSGBM's. The peer figures and
// the ground-truth scales are those of the data's README (measured outside this project).
#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/nav/stereo/disparity_metrics.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace marsokhod::nav {
namespace {

struct PeerPair {
  const char* name;
  double scale;             // ground truth = value / scale
  double largest_disparity; // max_gt_disp_px of PAIRS.tsv
  double stereo_bm;         // OpenCV StereoBM bad-1.0 %
  double stereo_sgbm;       // OpenCV StereoSGBM bad-1.0 %
};

constexpr PeerPair kPairs[] = {{"tsukuba", 16, 14.00, 15.6, 7.2},
                               {"venus", 8, 19.75, 22.5, 9.7},
                               {"aloe", 3, 70.33, 41.4, 33.3},
                               {"rocks1", 3, 56.67, 25.0, 19.4}};

std::filesystem::path stereo_data() {
  return std::filesystem::path(MARSOKHOD_SHARED_DATA) / "stereo";
}

double bad_percent(const PeerPair& pair) {
  const std::filesystem::path dir = stereo_data();
  const std::string name = pair.name;
  const imaging::Image<std::uint8_t> left = imaging::read_gray8(dir / (name + "_left.pgm"));
  const imaging::Image<std::uint8_t> right = imaging::read_gray8(dir / (name + "_right.pgm"));
  const imaging::Image<std::uint8_t> stored = imaging::read_gray8(dir / (name + "_gt.pgm"));
  imaging::Image<float> truth(stored.width(), stored.height());
  for (std::size_t i = 0; i < stored.size(); ++i)
    truth.data()[i] = static_cast<float>(stored.data()[i] / pair.scale);
  StereoOptions options;
  options.max_disparity = static_cast<int>(std::ceil(pair.largest_disparity));
  options.ground_prior = false; // these scenes are not views of the ground
  const StereoResult result = match_stereo(left.view(), right.view(), options);
  return score_bad_pixels(result.disparity.view(), truth.view(), {}, 1.0F).percent();
}

TEST(StereoRealData, BeatsStereoBmOnEveryPairAndMatchesStereoSgbmOnAverage) {
  if (!std::filesystem::exists(stereo_data() / "tsukuba_gt.pgm"))
    GTEST_SKIP() << "no stereo pairs in " << stereo_data();
  double ours = 0.0;
  double sgbm = 0.0;
  for (const PeerPair& pair : kPairs) {
    const double bad = bad_percent(pair);
    EXPECT_LT(bad, pair.stereo_bm) << pair.name;
    ours += bad;
    sgbm += pair.stereo_sgbm;
  }
  EXPECT_LE(ours / 4.0, sgbm / 4.0);
}

} // namespace
} // namespace marsokhod::nav
