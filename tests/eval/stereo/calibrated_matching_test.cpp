// Tests: vertical parallax calibration restoring row matching on rendered, misaligned pairs.
// Vertical parallax calibration on rendered pairs (paper, section 2): a right camera tilted by
// a known angle spoils row matching, and the map calibrated on one site restores it on another.
// In tests/eval because it needs the world's renderer and its exact ground truth.

#include "nav/stereo_test_support.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/nav/calibration/vertical_parallax_calibration.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"
#include "marsokhod/world/lighting/lighting.hpp"
#include "marsokhod/world/lighting/lit_surface.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/scene/rover_placement.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace marsokhod::nav {
namespace {

constexpr double kArcsecond = std::numbers::pi / (180.0 * 3600.0);

constexpr int kSize = 128;
// 1.5 rows at the image centre of a 128 px image: tilt = 1.5 / f_px radians.
const double kFocalPx = 12.0 / 7.0 * kSize;
const double kTiltArcsec = 1.5 / kFocalPx / kArcsecond;

struct Site {
  world::Terrain terrain;
  world::LitSurface surface;
  world::Renderer renderer;
  world::RoverPlacement placement;

  explicit Site(std::uint64_t seed)
      : terrain(world::Terrain::generate(settings(seed))),
        surface(terrain, world::lighting_preset(world::LightPreset::high_sun)), renderer(terrain),
        placement(world::place_rover(terrain.height, world::RoverPose{})) {}

  static world::TerrainSettings settings(std::uint64_t seed) {
    world::TerrainSettings s;
    s.seed = seed;
    s.size_m = 32.0;
    s.cell_m = 0.04;
    return s;
  }

  world::RenderedFrame render(double tilt_arcsec) const {
    imaging::RigParameters rig;
    rig.width_px = rig.height_px = kSize;
    rig.right_misalignment.tilt_arcsec = tilt_arcsec;
    world::RenderOptions options;
    options.noise_seed = terrain.settings.seed;
    // A camera's pixel integrates the light over its area; one ray per pixel would alias the
    // ground's fine texture, and a right image shifted by a fraction of a row would then differ
    // from the left by more than any resampling can restore.
    options.supersampling = 2;
    return renderer.render_with_ground_truth(imaging::StereoRig(rig), placement, surface, options);
  }
};

// Share of the ground-truth-valid pixels whose disparity lies within 1 px of the truth.
double matching_quality(const world::RenderedFrame& frame,
                        imaging::ImageView<const std::uint8_t> right) {
  imaging::RigParameters parameters;
  parameters.width_px = parameters.height_px = kSize;
  StereoOptions options = NavigationOptions::rover_stereo_defaults();
  options.max_disparity = rover_max_disparity(imaging::StereoRig(parameters), {});
  const StereoResult result = match_stereo(frame.images.left, right, options);
  return testing::share_within(result.disparity, frame.truth.disparity, frame.truth.valid, 1.0F);
}

class CalibratedMatching : public ::testing::Test {
protected:
  // One site to calibrate on and another to navigate on, as a rover calibrates once and then
  // applies the map to every later pair.
  static void SetUpTestSuite() {
    const world::RenderedFrame target = Site(11).render(kTiltArcsec);
    calibration_ = new CalibrationResult(calibrate_vertical_parallax(
        target.images.left, target.images.right, CalibrationOptions{.max_disparity = 60}));
    const Site site(5);
    aligned_ = new world::RenderedFrame(site.render(0.0));
    misaligned_ = new world::RenderedFrame(site.render(kTiltArcsec));
  }
  static void TearDownTestSuite() {
    delete calibration_;
    delete aligned_;
    delete misaligned_;
  }

  static CalibrationResult* calibration_;
  static world::RenderedFrame* aligned_;
  static world::RenderedFrame* misaligned_;
};

CalibrationResult* CalibratedMatching::calibration_ = nullptr;
world::RenderedFrame* CalibratedMatching::aligned_ = nullptr;
world::RenderedFrame* CalibratedMatching::misaligned_ = nullptr;

TEST_F(CalibratedMatching, TheShiftMatchesTheTiltTimesTheFocalLength) {
  const VerticalParallaxMap& map = calibration_->map;
  // Small-angle geometry (docs/camera.md): a tilt turns the right view so that a point at
  // (u, v) from the centre lands tilt (f + v^2 / f) rows lower. The tolerance is what matching
  // can tell apart: on this pair, removing any constant shift within 0.15 row of the truth
  // gives the same matching quality to within about 2 points (docs/navigation.md), so the map
  // needs no better. (150 block matches in a six-term fit leave about 0.05 row of noise; the
  // estimate runs about 0.1 row low, a bias the documentation reports.)
  const double tilt = kTiltArcsec * kArcsecond;
  const double centre = 0.5 * (kSize - 1);
  EXPECT_NEAR(map.shift_at(centre, centre), tilt * kFocalPx, 0.15);
  for (const double v : {-40.0, 0.0, 40.0})
    EXPECT_NEAR(map.shift_at(centre, centre + v), tilt * (kFocalPx + v * v / kFocalPx), 0.15)
        << "v = " << v;
  EXPECT_GT(calibration_->inliers, 50);
}

TEST_F(CalibratedMatching, TheMapAgreesWithTheRenderersExactVerticalParallax) {
  // The renderer's truth is v_left - v_right per left pixel; the map's shift is v_right -
  // v_left at the right pixel x - d.
  const world::GroundTruth& truth = misaligned_->truth;
  double error = 0.0;
  long pixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (truth.valid(x, y) == 0)
        continue;
      const double predicted = calibration_->map.shift_at(x - truth.disparity(x, y), y);
      error += std::fabs(predicted + truth.vertical_parallax(x, y));
      ++pixels;
    }
  ASSERT_GT(pixels, 1000);
  EXPECT_LT(error / static_cast<double>(pixels), 0.15); // as above
}

TEST_F(CalibratedMatching, QualityDropsWithTheMisalignmentAndCalibrationRestoresIt) {
  const double aligned = matching_quality(*aligned_, aligned_->images.right);
  const double misaligned = matching_quality(*misaligned_, misaligned_->images.right);
  const imaging::Image<std::uint8_t> restored =
      remove_vertical_parallax(misaligned_->images.right, calibration_->map);
  const double calibrated = matching_quality(*misaligned_, restored);
  RecordProperty("aligned", std::to_string(aligned));
  RecordProperty("misaligned", std::to_string(misaligned));
  RecordProperty("calibrated", std::to_string(calibrated));
  std::printf("within 1 px: aligned %.4f, misaligned %.4f, calibrated %.4f\n", aligned, misaligned,
              calibrated);
  EXPECT_LT(misaligned, 0.9 * aligned);
  EXPECT_GE(calibrated, 0.9 * aligned);
}

} // namespace
} // namespace marsokhod::nav
