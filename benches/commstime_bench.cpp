// Host cost of the emulator's hot path: Commstime, four channel communications per loop, each
// one a context switch between two simulated processes; the bare fiber switch it sits on is
// measured in the same run (bare_fiber_switch.cpp).

#include "marsokhod/emulator/kernel.hpp"
#include "marsokhod/emulator/node.hpp"
#include "marsokhod/emulator/platform.hpp"
#include "marsokhod/occam_port/commstime.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

using namespace marsokhod;

// The shipped platform, found beside this source file (benches/ and platforms/ are siblings).
emulator::NodeSpec t805_30() {
  const std::filesystem::path here(__FILE__);
  return emulator::load_platform(here.parent_path().parent_path() / "platforms" / "pc-card.toml")
      .nodes.front();
}

void run_commstime(benchmark::State& state, bool parallel_delta) {
  const emulator::NodeSpec spec = t805_30();
  const std::int64_t loops = state.range(0);
  std::int64_t communications = 0;
  for (auto _ : state) {
    emulator::Kernel kernel;
    emulator::Node node(kernel, spec);
    occam_port::CommstimeOptions options;
    options.loops = loops;
    options.parallel_delta = parallel_delta;
    occam_port::CommstimeResult result;
    occam_port::spawn_commstime(node, options, result);
    kernel.run();
    communications += result.communications;
    benchmark::DoNotOptimize(result.measured_time);
  }
  state.counters["ns_per_communication"] =
      benchmark::Counter(static_cast<double>(communications),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["communications"] = static_cast<double>(communications);
}

void BM_CommstimeSeqDelta(benchmark::State& state) {
  run_commstime(state, false);
}
void BM_CommstimeParDelta(benchmark::State& state) {
  run_commstime(state, true);
}

BENCHMARK(BM_CommstimeSeqDelta)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CommstimeParDelta)->Arg(100'000)->Unit(benchmark::kMillisecond);

} // namespace
