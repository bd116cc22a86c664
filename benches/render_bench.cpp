// Benchmark: the ray-casting stereo renderer and the build of its maximum mipmap.
// Ray-casting stereo renderer: a pair with ground truth per frame, and the one-off build of the
// maximum mipmap. The terrain (default settings, 48 m at 2 cm) is generated once, outside the
// timed loops. Target: a 256 x 256 pair with ground truth in under 50 ms on one core.
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/render/max_mipmap.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace marsokhod;

const world::Terrain& default_terrain() {
  static const world::Terrain terrain = world::Terrain::generate(world::TerrainSettings{});
  return terrain;
}

void BM_RenderPairWithGroundTruth(benchmark::State& state) {
  const world::Terrain& terrain = default_terrain();
  const world::LitSurface surface(terrain, world::lighting_preset(world::LightPreset::high_sun));
  const world::Renderer renderer(terrain);
  imaging::RigParameters parameters;
  parameters.width_px = parameters.height_px = static_cast<int>(state.range(0));
  const imaging::StereoRig rig(parameters);
  const world::RoverPlacement placement = world::place_rover(terrain.height, world::RoverPose{});
  for (auto _ : state) {
    world::RenderedFrame frame = renderer.render_with_ground_truth(rig, placement, surface);
    benchmark::DoNotOptimize(frame.images.left.data());
    benchmark::DoNotOptimize(frame.truth.disparity.data());
  }
  state.counters["pixels"] = static_cast<double>(parameters.width_px * parameters.height_px);
}
BENCHMARK(BM_RenderPairWithGroundTruth)->Arg(256)->Arg(128)->Unit(benchmark::kMillisecond);

void BM_BuildAcceleration(benchmark::State& state) {
  const world::Terrain& terrain = default_terrain();
  for (auto _ : state) {
    world::MaxMipmap mipmap(terrain.height);
    benchmark::DoNotOptimize(mipmap.max_height(mipmap.levels() - 1, 0, 0));
  }
  state.counters["nodes"] = static_cast<double>(terrain.height.nx()) * terrain.height.ny();
}
BENCHMARK(BM_BuildAcceleration)->Unit(benchmark::kMillisecond);

} // namespace
