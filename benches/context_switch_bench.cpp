// Benchmark: host cost of switching between simulated processes, and their memory.
// Host cost of switching between simulated processes, against a bare Boost.Context switch
// (bare_fiber_switch.cpp), and the memory of many live processes.

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

namespace {

using namespace marsokhod::emulator;

// Two processes on one CPU yielding to each other: one kernel process switch per yield.
void BM_KernelYieldSwitch(benchmark::State& state) {
  const std::int64_t yields = state.range(0);
  std::int64_t switches = 0;
  for (auto _ : state) {
    Kernel kernel;
    Cpu& cpu = kernel.add_cpu("node0");
    for (int i = 0; i < 2; ++i) {
      kernel.spawn(
          cpu, "p",
          [&kernel, yields] {
            for (std::int64_t n = 0; n < yields; ++n)
              kernel.yield();
          });
    }
    kernel.run();
    switches += static_cast<std::int64_t>(kernel.context_switches());
  }
  state.counters["ns_per_switch"] = benchmark::Counter(
      static_cast<double>(switches), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_KernelYieldSwitch)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

std::int64_t resident_kb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      std::int64_t kb = 0;
      status >> kb;
      return kb;
    }
    status.ignore(1 << 16, '\n');
  }
  return -1;
}

// 10,000 processes alive at once (each blocked after touching its stack), then killed.
void BM_TenThousandLiveProcesses(benchmark::State& state) {
  const auto count = static_cast<int>(state.range(0));
  const auto stack_bytes = static_cast<std::size_t>(state.range(1));
  std::int64_t peak_growth_kb = 0;
  for (auto _ : state) {
    const std::int64_t before = resident_kb();
    Kernel kernel(KernelOptions{stack_bytes});
    Cpu& cpu = kernel.add_cpu("node0");
    for (int i = 0; i < count; ++i) {
      kernel.spawn(
          cpu, "p",
          [&kernel] {
            volatile char frame[1024] = {};
            benchmark::DoNotOptimize(frame[0]);
            kernel.block(WaitInfo{});
          });
    }
    const RunResult result = kernel.run();
    if (result.reason != StopReason::deadlock ||
        kernel.live_processes() != static_cast<std::size_t>(count))
      state.SkipWithError("processes did not all block");
    peak_growth_kb = std::max(peak_growth_kb, resident_kb() - before);
  }
  state.counters["rss_growth_MB"] = static_cast<double>(peak_growth_kb) / 1024.0;
  state.counters["processes"] = count;
}
BENCHMARK(BM_TenThousandLiveProcesses)
    ->Args({10'000, 16 * 1024})
    ->Args({10'000, 32 * 1024})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace
