// Tests: the stereo renderer's rays, grey levels, noise, supersampling and misalignment.

#include "support/test_files.hpp"
#include "world/hand_scenes.hpp"

#include "marsokhod/world/render/camera_view.hpp"
#include "marsokhod/world/render/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace {

using namespace marsokhod;

using test_support::kPi;

world::RenderOptions noiseless_render() {
  world::RenderOptions options;
  options.noise_sigma = 0.0;
  return options;
}

// A generated site at default settings, shared by the tests of this file.
struct GeneratedSite {
  world::Terrain terrain = world::Terrain::generate(world::TerrainSettings{});
  world::Renderer renderer{terrain};
  world::RoverPlacement placement = world::place_rover(terrain.height, world::RoverPose{});
};

const GeneratedSite& generated_site() {
  static const GeneratedSite site;
  return site;
}

double bilinear_row_sample(const imaging::Image<std::uint8_t>& image, double x, int y) {
  const int x0 = static_cast<int>(std::floor(x));
  const double w = x - x0;
  return (1.0 - w) * image(x0, y) + w * image(x0 + 1, y);
}

TEST(Renderer, CameraViewCastsTheRigsRaysFromTheRigsCentres) {
  imaging::RigParameters p;
  p.right_misalignment.tilt_arcsec = 300.0;
  p.right_misalignment.roll_arcsec = -200.0;
  const imaging::StereoRig rig(p);
  world::RoverPlacement placement;
  placement.attitude = {3.0, -2.0};
  placement.level_to_world.translate(Eigen::Vector3d(1.0, -2.0, 0.3));
  placement.level_to_world.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  for (const imaging::Eye eye : {imaging::Eye::left, imaging::Eye::right}) {
    const world::CameraView view(rig, eye, placement);
    const Eigen::Vector3d centre =
        placement.level_to_world * rig.camera_to_level(eye, placement.attitude).translation();
    EXPECT_LT((view.centre() - centre).norm(), 1e-12);
    for (const auto& [u, v] : {std::pair{0.0, 0.0}, {255.0, 17.5}, {100.0, 250.0}}) {
      const Eigen::Vector3d expected =
          placement.level_to_world.linear() * rig.ray(eye, u, v, placement.attitude);
      EXPECT_LT((view.ray(u, v) - expected).norm(), 1e-12);
      const auto pixel = view.project(view.centre() + 7.0 * view.ray(u, v));
      ASSERT_TRUE(pixel);
      EXPECT_NEAR(pixel->x(), u, 1e-9);
      EXPECT_NEAR(pixel->y(), v, 1e-9);
    }
  }
}

// Flat ground of constant albedo under a sun without sub-grid texture: every ground pixel has
// the Lambertian radiance albedo * (ambient + sun * sin(sun elevation)).
struct UniformScene {
  world::Terrain terrain =
      test::terrain_from(test::flat_field(6.0, 0.05), [](double, double) { return 0.4f; });
  world::Lighting light = [] {
    world::Lighting l = world::lighting_preset(world::LightPreset::high_sun);
    l.fine_texture = 0.0;
    return l;
  }();
  world::LitSurface surface{terrain, light};
  world::Renderer renderer{terrain};
};

TEST(Renderer, GreyLevelIsExposedLambertianRadianceAndTheSkyIsSkyGrey) {
  const UniformScene scene;
  const imaging::RigParameters p;
  const auto frame = scene.renderer.render_with_ground_truth(
      imaging::StereoRig(p), test::level_placement(), scene.surface, noiseless_render());
  const world::Lighting& l = scene.light;
  const double radiance = 0.4 * (l.ambient + l.sun * std::sin(l.sun_elevation_deg * kPi / 180.0));
  const double ground = std::clamp(std::round(l.exposure * radiance), 0.0, 255.0);
  const double sky = std::round(l.sky_grey);
  int ground_pixels = 0;
  int sky_pixels = 0;
  for (int v = 0; v < p.height_px; ++v)
    for (int u = 0; u < p.width_px; ++u) {
      const bool visible = frame.truth.visible(u, v) != 0;
      EXPECT_EQ(frame.images.left(u, v), visible ? ground : sky) << u << "," << v;
      ground_pixels += visible;
      sky_pixels += !visible;
    }
  EXPECT_GT(ground_pixels, 1000);
  EXPECT_GT(sky_pixels, 1000);
}

TEST(Renderer, SensorNoiseIsGaussianWithTheRequestedSigma) {
  const UniformScene scene;
  world::RenderOptions noisy;
  noisy.noise_sigma = 3.0;
  noisy.noise_seed = 11;
  const auto frame = scene.renderer.render_with_ground_truth(
      imaging::StereoRig{}, test::level_placement(), scene.surface, noisy);
  const world::Lighting& l = scene.light;
  const double ground =
      l.exposure * 0.4 * (l.ambient + l.sun * std::sin(l.sun_elevation_deg * kPi / 180.0));
  double sum = 0.0;
  double sum_sq = 0.0;
  const imaging::Image<std::uint8_t>& image = frame.images.left;
  for (int v = 0; v < image.height(); ++v)
    for (int u = 0; u < image.width(); ++u) {
      const double exact = frame.truth.visible(u, v) ? ground : l.sky_grey;
      const double e = image(u, v) - exact;
      sum += e;
      sum_sq += e * e;
    }
  const auto n = static_cast<double>(image.size());
  const double mean = sum / n;
  // Rounding to integers adds a uniform error of variance 1/12.
  EXPECT_NEAR(mean, 0.0, 0.05);
  EXPECT_NEAR(std::sqrt(sum_sq / n - mean * mean), std::sqrt(9.0 + 1.0 / 12.0), 0.06);
  EXPECT_NE(frame.images.left, frame.images.right); // independent streams for the two cameras
}

TEST(Renderer, SameSeedGivesIdenticalFramesAndAnotherSeedOtherNoise) {
  const UniformScene scene;
  const imaging::StereoRig rig;
  world::RenderOptions options;
  options.noise_seed = 5;
  const auto a =
      scene.renderer.render_with_ground_truth(rig, test::level_placement(), scene.surface, options);
  const auto b =
      scene.renderer.render_with_ground_truth(rig, test::level_placement(), scene.surface, options);
  EXPECT_EQ(a.images.left, b.images.left);
  EXPECT_EQ(a.images.right, b.images.right);
  EXPECT_EQ(a.truth.disparity, b.truth.disparity);
  EXPECT_EQ(a.truth.valid, b.truth.valid);
  options.noise_seed = 6;
  const auto c =
      scene.renderer.render_with_ground_truth(rig, test::level_placement(), scene.surface, options);
  EXPECT_NE(a.images.left, c.images.left);
  EXPECT_NE(a.images.right, c.images.right);
  EXPECT_EQ(a.truth.disparity, c.truth.disparity); // the geometry does not depend on noise
}

TEST(Renderer, SupersamplingChangesTheImagesButNotTheGroundTruth) {
  const world::Terrain terrain =
      test::terrain_from(test::flat_field(6.0, 0.02), test::smooth_albedo);
  const world::LitSurface surface(terrain, world::lighting_preset(world::LightPreset::low_sun));
  const world::Renderer renderer(terrain);
  const imaging::StereoRig rig;
  world::RenderOptions smooth = noiseless_render();
  smooth.supersampling = 3;
  const auto one =
      renderer.render_with_ground_truth(rig, test::level_placement(), surface, noiseless_render());
  const auto nine =
      renderer.render_with_ground_truth(rig, test::level_placement(), surface, smooth);
  EXPECT_EQ(one.truth.disparity, nine.truth.disparity);
  EXPECT_NE(one.images.left, nine.images.left);
}

TEST(Renderer, RejectsImpossibleOptions) {
  const UniformScene scene;
  const imaging::StereoRig rig;
  world::RenderOptions bad;
  bad.supersampling = 0;
  EXPECT_THROW(scene.renderer.render(rig, test::level_placement(), scene.surface, bad),
               std::invalid_argument);
  bad = {};
  bad.noise_sigma = -1.0;
  EXPECT_THROW(scene.renderer.render(rig, test::level_placement(), scene.surface, bad),
               std::invalid_argument);
}

// Warping the right image by the ground-truth disparity must give back the left image: the
// images and the ground truth describe the same geometry.
// Pixels' rays start their walk where the ray below ended when the terrain's slope bound
// allows it; the ground truth must still be each centre ray's own first hit.
TEST(Renderer, EveryPixelRecordsTheFirstHitOfItsOwnCentreRay) {
  const GeneratedSite& site = generated_site();
  const imaging::StereoRig rig;
  const world::LitSurface surface(site.terrain,
                                  world::lighting_preset(world::LightPreset::high_sun));
  const auto frame = site.renderer.render_with_ground_truth(rig, site.placement, surface);
  const world::CameraView left(rig, imaging::Eye::left, site.placement);
  const Eigen::Isometry3d world_to_level = site.placement.level_to_world.inverse();
  int hits = 0;
  for (int v = 0; v < rig.height(); ++v)
    for (int u = 0; u < rig.width(); ++u) {
      const Eigen::Vector3d direction = left.ray(u, v);
      const auto hit = site.renderer.acceleration().first_hit(left.centre(), direction);
      ASSERT_EQ(hit.has_value(), frame.truth.visible(u, v) != 0) << u << "," << v;
      if (!hit)
        continue;
      ++hits;
      const Eigen::Vector3d level = world_to_level * (left.centre() + *hit * direction);
      EXPECT_NEAR(frame.truth.range(u, v), level.head<2>().norm(), 1e-4) << u << "," << v;
    }
  EXPECT_GT(hits, rig.width() * rig.height() / 2);
}

TEST(Renderer, RightImageWarpedByGroundTruthDisparityReproducesTheLeftForEveryLight) {
  const GeneratedSite& site = generated_site();
  const imaging::StereoRig rig;
  for (const auto preset : {world::LightPreset::high_sun, world::LightPreset::overexposed,
                            world::LightPreset::dark_wet, world::LightPreset::low_sun}) {
    const world::LitSurface surface(site.terrain, world::lighting_preset(preset));
    const auto frame =
        site.renderer.render_with_ground_truth(rig, site.placement, surface, noiseless_render());
    double error = 0.0;
    int pixels = 0;
    for (int v = 0; v < rig.height(); ++v)
      for (int u = 0; u < rig.width(); ++u) {
        const double x = u - frame.truth.disparity(u, v);
        if (!frame.truth.valid(u, v) || x < 0.0 || x > rig.width() - 1.0)
          continue;
        error += std::abs(bilinear_row_sample(frame.images.right, x, v) - frame.images.left(u, v));
        ++pixels;
      }
    ASSERT_GT(pixels, rig.width() * rig.height() / 3) << world::to_string(preset);
    EXPECT_LT(error / pixels, 3.0) << world::to_string(preset);
  }
}

// Shift s (px) that best maps b onto a along the columns: a(u, v) ~ b(u, v + s).
double vertical_shift(const imaging::Image<std::uint8_t>& a,
                      const imaging::Image<std::uint8_t>& b) {
  double best_shift = 0.0;
  double best_cost = 1e300;
  for (double s = -4.0; s <= 4.0; s += 0.02) {
    double cost = 0.0;
    for (int v = 8; v < a.height() - 8; ++v) {
      const int v0 = static_cast<int>(std::floor(v + s));
      const double w = v + s - v0;
      for (int u = 0; u < a.width(); ++u) {
        const double sample = (1.0 - w) * b(u, v0) + w * b(u, v0 + 1);
        cost += (a(u, v) - sample) * (a(u, v) - sample);
      }
    }
    if (cost < best_cost) {
      best_cost = cost;
      best_shift = s;
    }
  }
  return best_shift;
}

TEST(Renderer, RightCameraTiltShiftsItsRowsByFocalTimesTilt) {
  const GeneratedSite& site = generated_site();
  const world::LitSurface surface(site.terrain,
                                  world::lighting_preset(world::LightPreset::high_sun));
  const double tilt_arcsec = 600.0;
  imaging::RigParameters tilted;
  tilted.right_misalignment.tilt_arcsec = tilt_arcsec;
  const auto ideal = site.renderer.render_view(imaging::StereoRig{}, imaging::Eye::right,
                                               site.placement, surface, noiseless_render());
  const auto frame = site.renderer.render_with_ground_truth(
      imaging::StereoRig(tilted), site.placement, surface, noiseless_render());
  const double f = tilted.focal_mm / tilted.sensor_mm * tilted.width_px;
  const double expected = f * tilt_arcsec / 3600.0 * kPi / 180.0; // about 1.28 px
  const double shift = vertical_shift(frame.images.right, ideal);
  EXPECT_NEAR(std::abs(shift), expected, 0.15);
  // The ground truth's vertical parallax v_left - v_right says the same.
  std::vector<float> parallax;
  for (int v = 0; v < tilted.height_px; ++v)
    for (int u = 0; u < tilted.width_px; ++u)
      if (frame.truth.valid(u, v))
        parallax.push_back(frame.truth.vertical_parallax(u, v));
  ASSERT_FALSE(parallax.empty());
  std::nth_element(parallax.begin(), parallax.begin() + parallax.size() / 2, parallax.end());
  EXPECT_NEAR(parallax[parallax.size() / 2], shift, 0.15);
}

} // namespace
