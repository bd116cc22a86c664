// Tests: the hybrid occlusion mask against an occlusion ray cast for every pixel.
// The occlusion mask decided from the right view's depths, with rays only where those are
// ambiguous, against the reference that casts an occlusion ray for every pixel.
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/render/ground_truth.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <gtest/gtest.h>

namespace {

using namespace marsokhod;

struct DefaultSite {
  world::Terrain terrain = world::Terrain::generate(world::TerrainSettings{});
  world::LitSurface surface{terrain, world::lighting_preset(world::LightPreset::high_sun)};
  world::Renderer renderer{terrain};
};

const DefaultSite& default_site() {
  static const DefaultSite site;
  return site;
}

world::GroundTruth truth_at(double heading_deg, bool cast_every_ray) {
  const DefaultSite& site = default_site();
  imaging::RigParameters parameters;
  parameters.width_px = parameters.height_px = 256;
  const imaging::StereoRig rig(parameters);
  world::RoverPose pose;
  pose.heading_deg = heading_deg;
  const world::RoverPlacement placement = world::place_rover(site.terrain.height, pose);
  world::RenderOptions options;
  options.cast_every_occlusion_ray = cast_every_ray;
  return site.renderer.render_with_ground_truth(rig, placement, site.surface, options).truth;
}

class HybridOcclusion : public testing::TestWithParam<double> {};

TEST_P(HybridOcclusion, AgreesWithAnOcclusionRayOnEveryPixelOfTheDefaultSite) {
  const world::GroundTruth hybrid = truth_at(GetParam(), false);
  const world::GroundTruth reference = truth_at(GetParam(), true);
  // The scene must exercise both outcomes, or agreement would prove little.
  const world::GroundTruthStats stats = world::summarize(reference);
  EXPECT_GT(stats.occluded, 0);
  EXPECT_GT(stats.valid, stats.pixels / 4);
  long differing = 0;
  for (int v = 0; v < reference.occluded.height(); ++v)
    for (int u = 0; u < reference.occluded.width(); ++u)
      if (hybrid.occluded(u, v) != reference.occluded(u, v) ||
          hybrid.valid(u, v) != reference.valid(u, v))
        ++differing;
  EXPECT_EQ(differing, 0);
}

INSTANTIATE_TEST_SUITE_P(Headings, HybridOcclusion, testing::Values(0.0, 90.0, 180.0, 270.0));

} // namespace
