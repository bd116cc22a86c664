// Benchmark: Commstime, the host cost of the emulator's channel communication hot path.
// Host cost of the emulator's hot path: Commstime, four channel communications per loop, each
// one a context switch between two simulated processes; the bare fiber switch it sits on is
// measured in the same run (bare_fiber_switch.cpp).

#include "bare_fiber_switch.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/occam_port/commstime.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>

namespace {

using namespace marsokhod;

// The shipped platform, found beside this source file (benches/ and platforms/ are siblings).
emulator::NodeSpec t805_30() {
  const std::filesystem::path here(__FILE__);
  return emulator::load_platform(here.parent_path().parent_path() / "platforms" / "pc-card.toml")
      .nodes.front();
}

// One Commstime run on a fresh kernel and node; returns the communications it made.
std::int64_t run_commstime_once(const emulator::NodeSpec& spec, std::int64_t loops,
                                bool parallel_delta) {
  emulator::Kernel kernel;
  emulator::Node node(kernel, spec);
  occam_port::CommstimeOptions options;
  options.loops = loops;
  options.parallel_delta = parallel_delta;
  occam_port::CommstimeResult result;
  occam_port::spawn_commstime(node, options, result);
  kernel.run();
  benchmark::DoNotOptimize(result.measured_time);
  return result.communications;
}

benchmark::Counter per(std::int64_t count) {
  return benchmark::Counter(static_cast<double>(count),
                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void run_commstime(benchmark::State& state, bool parallel_delta) {
  const emulator::NodeSpec spec = t805_30();
  const std::int64_t loops = state.range(0);
  std::int64_t communications = 0;
  for (auto _ : state)
    communications += run_commstime_once(spec, loops, parallel_delta);
  state.counters["ns_per_communication"] = per(communications);
  state.counters["communications"] = static_cast<double>(communications);
}

// SEQ Commstime and as many bare fiber switches as it made communications, one right after
// the other in every iteration, so that both see the host at the same speed: the host drifts
// by a quarter within one run, and the ratio, the cost of a communication in bare switches,
// says what the absolute figure would be on the host as it was at any other time.
void BM_CommstimeSeqAgainstBareSwitch(benchmark::State& state) {
  const emulator::NodeSpec spec = t805_30();
  const std::int64_t loops = state.range(0);
  std::int64_t communications = 0;
  double commstime_seconds = 0.0;
  double bare_seconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t made = run_commstime_once(spec, loops, false);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bare_seconds += benches::time_bare_fiber_switches(made);
    commstime_seconds += seconds;
    communications += made;
    state.SetIterationTime(seconds);
  }
  state.counters["ns_per_communication"] = per(communications);
  state.counters["ns_per_bare_switch"] =
      benchmark::Counter(1e9 * bare_seconds / static_cast<double>(communications));
  state.counters["bare_switches_per_communication"] =
      benchmark::Counter(commstime_seconds / bare_seconds);
}

void BM_CommstimeSeqDelta(benchmark::State& state) {
  run_commstime(state, false);
}
void BM_CommstimeParDelta(benchmark::State& state) {
  run_commstime(state, true);
}

BENCHMARK(BM_CommstimeSeqDelta)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CommstimeParDelta)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CommstimeSeqAgainstBareSwitch)
    ->Arg(100'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

} // namespace
