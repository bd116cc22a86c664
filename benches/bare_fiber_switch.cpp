// The floor any process switch sits on, linked into every emulator benchmark so that it is
// measured in the same run: two Boost.Context fibers handing control back and forth. The host's
// speed drifts from one run to the next (a KVM guest), and the ratio to this switch does not.

#include <benchmark/benchmark.h>
#include <boost/context/fiber.hpp>

namespace {

void BM_BareFiberSwitch(benchmark::State& state) {
  namespace ctx = boost::context;
  bool done = false;
  ctx::fiber other([&done](ctx::fiber&& back) {
    while (!done) {
      back = std::move(back).resume();
    }
    return std::move(back);
  });
  for (auto _ : state) {
    other = std::move(other).resume();
  }
  done = true;
  std::move(other).resume();
  state.counters["ns_per_switch"] =
      benchmark::Counter(static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BareFiberSwitch);

} // namespace
