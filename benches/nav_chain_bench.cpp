// Benchmark: one navigation cycle's chain, stereo to drive commands, at 256 x 256.
// The navigation chain of one cycle at the paper's 256 x 256: stereo, range and elevation,
// prohibited zones, safest path and drive commands (target: at most 5 ms on one core), each
// stage after stereo on its own, and the chain with a counting meter to show what metering
// costs. The scene (default site, seed 1, high sun) is rendered once, outside the timed loops.
#include "marsokhod/nav/calibration/vertical_parallax.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace marsokhod;

struct Scene {
  imaging::StereoRig rig;
  world::RenderedFrame frame;
  imaging::Attitude attitude;
};

const Scene& scene() {
  static const Scene made = [] {
    const world::Terrain terrain = world::Terrain::generate(world::TerrainSettings{});
    const world::LitSurface surface(terrain, world::lighting_preset(world::LightPreset::high_sun));
    const imaging::StereoRig rig{imaging::RigParameters{}};
    const world::RoverPlacement placement = world::place_rover(terrain.height, world::RoverPose{});
    return Scene{rig, world::Renderer(terrain).render_with_ground_truth(rig, placement, surface),
                 placement.attitude};
  }();
  return made;
}

nav::NavigationOptions options_for(const Scene& s) {
  nav::NavigationOptions options;
  options.attitude = s.attitude;
  return options;
}

template <class Meter>
void run_chain(benchmark::State& state, Meter& meter, int footprint_paths = -1) {
  const Scene& s = scene();
  nav::NavigationOptions options = options_for(s);
  if (footprint_paths >= 0)
    options.footprint.paths = footprint_paths;
  for (auto _ : state) {
    nav::NavigationResult result =
        nav::navigate(s.frame.images.left, s.frame.images.right, s.rig, options, meter);
    benchmark::DoNotOptimize(result.plan.pixels.data());
  }
  state.SetLabel(nav::navigate(s.frame.images.left, s.frame.images.right, s.rig, options).found()
                     ? "path found"
                     : "no path");
}

void BM_NavChain256(benchmark::State& state) {
  run_chain(state, nav::null_meter);
}
BENCHMARK(BM_NavChain256)->Unit(benchmark::kMillisecond);

// The chain as it was before the footprint check of the chosen path, for the check's cost.
void BM_NavChain256WithoutFootprintCheck(benchmark::State& state) {
  run_chain(state, nav::null_meter, 0);
}
BENCHMARK(BM_NavChain256WithoutFootprintCheck)->Unit(benchmark::kMillisecond);

void BM_NavChain256Counting(benchmark::State& state) {
  nav::CountingMeter meter;
  run_chain(state, meter);
  state.counters["work_units_per_cycle"] =
      static_cast<double>(meter.total()) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_NavChain256Counting)->Unit(benchmark::kMillisecond);

// Everything after stereo, from the matcher's disparity.
void BM_NavAfterStereo256(benchmark::State& state) {
  const Scene& s = scene();
  const nav::NavigationOptions options = options_for(s);
  const nav::NavigationResult matched =
      nav::navigate(s.frame.images.left, s.frame.images.right, s.rig, options);
  for (auto _ : state) {
    nav::NavigationResult result =
        nav::navigate_disparity(matched.stereo.disparity, matched.stereo.valid, s.rig, options);
    benchmark::DoNotOptimize(result.plan.pixels.data());
  }
}
BENCHMARK(BM_NavAfterStereo256)->Unit(benchmark::kMicrosecond);

// What a calibration adds to every cycle: removing the vertical parallax map from the right
// image (a 1.5-row shift with gentle slopes and curvature, as a tilted camera gives).
template <nav::VerticalInterpolation Interpolation>
void BM_RemoveVerticalParallax256(benchmark::State& state) {
  const Scene& s = scene();
  const nav::VerticalParallaxMap map{256, 256, {1.5, 1e-3, -2e-3, 1e-6, 2e-6, 3.4e-6}};
  for (auto _ : state) {
    imaging::Image<std::uint8_t> aligned =
        nav::remove_vertical_parallax(s.frame.images.right, map, Interpolation);
    benchmark::DoNotOptimize(aligned.data());
  }
}
BENCHMARK(BM_RemoveVerticalParallax256<nav::VerticalInterpolation::linear>)
    ->Name("BM_RemoveVerticalParallax256")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RemoveVerticalParallax256<nav::VerticalInterpolation::cubic>)
    ->Name("BM_RemoveVerticalParallax256_cubic")
    ->Unit(benchmark::kMicrosecond);

void BM_Terrain256(benchmark::State& state) {
  const Scene& s = scene();
  for (auto _ : state) {
    nav::TerrainPoints terrain =
        nav::reconstruct_terrain(s.frame.truth.disparity, s.rig, s.attitude);
    benchmark::DoNotOptimize(terrain.elevation.data());
  }
}
BENCHMARK(BM_Terrain256)->Unit(benchmark::kMicrosecond);

void BM_Zones256(benchmark::State& state) {
  const Scene& s = scene();
  const nav::TerrainPoints terrain =
      nav::reconstruct_terrain(s.frame.truth.disparity, s.rig, s.attitude);
  for (auto _ : state) {
    nav::ZoneMap zones = nav::find_zones(terrain, {}, nav::ZoneOptions{});
    benchmark::DoNotOptimize(zones.zone.data());
  }
}
BENCHMARK(BM_Zones256)->Unit(benchmark::kMicrosecond);

void BM_PathAndCommands256(benchmark::State& state) {
  const Scene& s = scene();
  const nav::TerrainPoints terrain =
      nav::reconstruct_terrain(s.frame.truth.disparity, s.rig, s.attitude);
  const nav::ZoneMap zones = nav::find_zones(terrain, {}, nav::ZoneOptions{});
  for (auto _ : state) {
    nav::PathPlan plan = nav::plan_path(terrain, zones, nav::PlannerOptions{});
    if (plan.found) {
      nav::DrivePlan drive = nav::plan_drive(terrain, plan.pixels, nav::DriveOptions{});
      benchmark::DoNotOptimize(drive.commands.data());
    }
    benchmark::DoNotOptimize(plan.pixels.data());
  }
}
BENCHMARK(BM_PathAndCommands256)->Unit(benchmark::kMicrosecond);

} // namespace
