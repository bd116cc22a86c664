// Benchmark floor: the bare Boost.Context fiber switch, timed in the emulator benchmarks' run.
// The floor any process switch sits on, linked into every emulator benchmark so that it is
// measured in the same run: two Boost.Context fibers handing control back and forth. The host's
// speed drifts by a quarter within one run (a KVM guest); the ratio to this switch drifts less.

#include "bare_fiber_switch.hpp"

#include <benchmark/benchmark.h>
#include <boost/context/fiber.hpp>

#include <chrono>

namespace marsokhod::benches {

double time_bare_fiber_switches(std::int64_t switches) {
  namespace ctx = boost::context;
  bool done = false;
  ctx::fiber other([&done](ctx::fiber&& back) {
    while (!done)
      back = std::move(back).resume();
    return std::move(back);
  });
  const auto start = std::chrono::steady_clock::now();
  for (std::int64_t i = 0; i < switches; ++i)
    other = std::move(other).resume();
  const auto end = std::chrono::steady_clock::now();
  done = true;
  std::move(other).resume();
  return std::chrono::duration<double>(end - start).count();
}

namespace {

void BM_BareFiberSwitch(benchmark::State& state) {
  constexpr std::int64_t kSwitches = 1 << 20;
  for (auto _ : state)
    state.SetIterationTime(time_bare_fiber_switches(kSwitches));
  state.counters["ns_per_switch"] =
      benchmark::Counter(static_cast<double>(state.iterations() * kSwitches),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BareFiberSwitch)->UseManualTime()->Unit(benchmark::kMillisecond);

} // namespace
} // namespace marsokhod::benches
