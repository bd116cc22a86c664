// Benchmark: one emulated navigation cycle at 128 x 128 against the native chain on the same
// pair, in the same run (targets: at most 50 ms of host time per emulated onboard cycle and at
// most 10 times the native chain). The pair (world seed 1, the default site) is rendered once,
// outside the timed loops. The onboard cycle runs as shipped, in the modules' 256 KB (the
// matcher's bands, the terrain kept as the disparity, the zones' grid in strips), and on
// modules given 2 MB each (what-if, `emulate --external-kb 2048`: the whole-image stages); the
// PC card runs as shipped.
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <stdexcept>

namespace {

using namespace marsokhod;

struct Site {
  world::SceneDescription scene;
  world::RenderedFrame frame;
  imaging::StereoRig rig;
};

const Site& site() {
  static const Site made = [] {
    world::SceneDescription scene = world::default_scene(1, 128);
    world::RenderedFrame frame = world::render_site(scene);
    const imaging::StereoRig rig(scene.rig);
    return Site{std::move(scene), std::move(frame), rig};
  }();
  return made;
}

struct Machine {
  emulator::PlatformSpec platform;
  nav_program::Placement placement;
  std::optional<std::size_t> external_bytes;
};

Machine machine(const std::string& name, std::optional<std::size_t> external_bytes) {
  const emulator::PlatformSpec platform =
      emulator::load_platform(emulator::find_platform_file(name + ".toml"));
  return {platform,
          nav_program::load_placement(nav_program::default_placement_file(platform), platform,
                                      nav_program::navigation_program_shape()),
          external_bytes};
}

nav::NavigationOptions options() {
  nav::NavigationOptions made;
  made.attitude = site().scene.placement.attitude;
  return made;
}

nav_program::CycleEmulation emulate(const Machine& m) {
  const Site& s = site();
  const nav_program::CycleInput input{
      s.frame.images.left, s.frame.images.right, &s.rig, options(), {}};
  nav_program::CycleEmulation run = nav_program::emulate_navigation_cycle(
      input, nav_program::CycleSetup{&m.platform, &m.placement, m.external_bytes, nullptr,
                                     nav_program::kOccamStyleFactor, nullptr, std::nullopt});
  if (run.memory_fault)
    throw std::runtime_error("the benchmark cycle ran out of memory on " + run.memory_fault->node);
  return run;
}

void BM_NativeChain128(benchmark::State& state) {
  const Site& s = site();
  const nav::NavigationOptions o = options();
  for (auto _ : state) {
    nav::NavigationResult result =
        nav::navigate(s.frame.images.left, s.frame.images.right, s.rig, o);
    benchmark::DoNotOptimize(result.plan.pixels.data());
  }
}
BENCHMARK(BM_NativeChain128)->Unit(benchmark::kMillisecond);

void emulated_cycle(benchmark::State& state, const Machine& m) {
  double emulated_seconds = 0.0;
  for (auto _ : state) {
    const nav_program::CycleEmulation run = emulate(m);
    emulated_seconds = emulator::to_seconds(run.emulated);
    benchmark::DoNotOptimize(run.emulated);
  }
  state.counters["emulated_s"] = emulated_seconds;
}

void BM_EmulatedCycle128PcCard(benchmark::State& state) {
  emulated_cycle(state, machine("pc-card", std::nullopt));
}
BENCHMARK(BM_EmulatedCycle128PcCard)->Unit(benchmark::kMillisecond);

void BM_EmulatedCycle128Onboard(benchmark::State& state) {
  emulated_cycle(state, machine("onboard", std::nullopt));
}
BENCHMARK(BM_EmulatedCycle128Onboard)->Unit(benchmark::kMillisecond);

void BM_EmulatedCycle128Onboard2MB(benchmark::State& state) {
  emulated_cycle(state, machine("onboard", 2048 * 1024));
}
BENCHMARK(BM_EmulatedCycle128Onboard2MB)->Unit(benchmark::kMillisecond);

// Both in one loop, so that the ratio compares like with like on the same machine state.
void BM_EmulatedOverNativeRatio128(benchmark::State& state) {
  const Machine m = machine("onboard", std::nullopt);
  const Site& s = site();
  const nav::NavigationOptions o = options();
  using Clock = std::chrono::steady_clock;
  Clock::duration native{};
  Clock::duration emulated{};
  for (auto _ : state) {
    const auto t0 = Clock::now();
    nav::NavigationResult result =
        nav::navigate(s.frame.images.left, s.frame.images.right, s.rig, o);
    benchmark::DoNotOptimize(result.plan.pixels.data());
    const auto t1 = Clock::now();
    const nav_program::CycleEmulation run = emulate(m);
    benchmark::DoNotOptimize(run.emulated);
    emulated += Clock::now() - t1;
    native += t1 - t0;
  }
  state.counters["emulated_over_native"] =
      std::chrono::duration<double>(emulated) / std::chrono::duration<double>(native);
}
BENCHMARK(BM_EmulatedOverNativeRatio128)->Unit(benchmark::kMillisecond);

} // namespace
