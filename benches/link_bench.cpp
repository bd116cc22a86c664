// Benchmark: host cost per emulated byte of the link model, framing alone and full streams.
// Host cost of the link model: nanoseconds of host time per emulated byte, for the pure framing
// state machine and for a full stream between two emulated nodes (kernel events, processes).

#include "marsokhod/emulator/links/link_framing.hpp"
#include "marsokhod/emulator/links/link_stream.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <benchmark/benchmark.h>

namespace {

namespace emu = marsokhod::emulator;

const emu::PlatformSpec& onboard() {
  static const emu::PlatformSpec platform =
      emu::load_platform(emu::find_platform_file("onboard.toml"));
  return platform;
}

void BM_LinkFramingOneWay(benchmark::State& state) {
  const auto timing = emu::LinkTiming::from(onboard().link_timing, 10);
  const auto bytes = static_cast<std::uint64_t>(state.range(0));
  for (auto _ : state) {
    emu::LinkFraming link(timing);
    link.offer_output(0, 0, bytes);
    link.offer_input(1, 0, bytes);
    while (link.step().kind != emu::LinkStep::Kind::none) {
    }
    benchmark::DoNotOptimize(link.now());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LinkFramingOneWay)->Arg(100'000);

void BM_LinkStream(benchmark::State& state) {
  emu::LinkStreamOptions options;
  options.bytes = static_cast<std::uint64_t>(state.range(0));
  options.both_ways = state.range(1) != 0;
  double emulated_rate = 0;
  for (auto _ : state) {
    const emu::LinkStreamResult result = emu::run_link_stream(onboard(), options);
    emulated_rate = result.bytes_per_second;
    benchmark::DoNotOptimize(result.elapsed);
  }
  const auto moved = state.range(0) * (options.both_ways ? 2 : 1);
  state.SetItemsProcessed(state.iterations() * moved);
  state.counters["host_ns_per_byte"] =
      benchmark::Counter(static_cast<double>(state.iterations() * moved),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["emulated_KB_per_s"] = emulated_rate / 1000.0;
}
BENCHMARK(BM_LinkStream)->Args({100'000, 0})->Args({100'000, 1})->Unit(benchmark::kMillisecond);

} // namespace
