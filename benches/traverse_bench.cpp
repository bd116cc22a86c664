// One traverse trial as `eval traverse` runs it: the 100 m x 30 m site generated, then every
// cycle's render, native navigation and drive on the true ground, on one core. Target: at most 3 s
// a trial at k = 0.10 (the sweep of 700 trials in 25 minutes on two cores). Also the site alone and
// the loop alone, to say where the time goes.

#include "marsokhod/eval/traverse/traverse.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace marsokhod;

eval::TraverseSettings trial(std::uint64_t seed, double rocks) {
  eval::TraverseSettings s;
  s.seed = seed;
  s.rocks = rocks;
  return s;
}

void BM_TraverseTrial(benchmark::State& state) {
  const eval::TraverseSettings s = trial(2, 0.10);
  for (auto _ : state) {
    const eval::TraverseResult r = eval::run_traverse(s);
    benchmark::DoNotOptimize(r.distance_m);
    state.counters["cycles"] = static_cast<double>(r.cycles.size());
  }
}
BENCHMARK(BM_TraverseTrial)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_TraverseSite(benchmark::State& state) {
  const eval::TraverseSettings s = trial(2, 0.10);
  for (auto _ : state) {
    const world::Terrain terrain = world::Terrain::generate(eval::traverse_site(s));
    benchmark::DoNotOptimize(terrain.height.at(0, 0));
  }
}
BENCHMARK(BM_TraverseSite)->Unit(benchmark::kMillisecond)->Iterations(3);

// The loop on a site made once: rendering, navigation and driving for every cycle (a rock-free
// site, so the course is whole).
void BM_TraverseLoop(benchmark::State& state) {
  const eval::TraverseSettings s = trial(1, 0.0);
  const world::Terrain terrain = world::Terrain::generate(eval::traverse_site(s));
  for (auto _ : state) {
    const eval::TraverseResult r = eval::run_traverse(terrain, s);
    benchmark::DoNotOptimize(r.distance_m);
    state.counters["cycles"] = static_cast<double>(r.cycles.size());
  }
}
BENCHMARK(BM_TraverseLoop)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace
