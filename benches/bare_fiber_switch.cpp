// Bare fiber switches, linked into every emulator benchmark so that they are measured in the
// same run: two Boost.Context fibers handing control back and forth, with Boost's public
// fiber::resume and with the emulator's returning switch, the two switches the kernel can be
// built with (MARSOKHOD_FIBER_SWITCH). The host's speed drifts by a quarter within one run (a
// KVM guest); the ratio of two figures taken side by side drifts less.

#include "bare_fiber_switch.hpp"

#include "fiber.hpp"

#include <benchmark/benchmark.h>

#include <chrono>

namespace marsokhod::benches {

namespace {

namespace ctx = boost::context;

// Times `switches` switches from this fiber to another that switches straight back, both
// with `switch_fiber` (one of the emulator's, fiber.hpp).
template <void (*switch_fiber)(ctx::fiber&, ctx::fiber* const&)>
double time_switches(std::int64_t switches) {
  bool done = false;
  ctx::fiber other([&done](ctx::fiber&& back) {
    ctx::fiber* const slot = &back;
    while (!done) {
      switch_fiber(back, slot);
    }
    return std::move(back);
  });
  ctx::fiber* const slot = &other;
  const auto start = std::chrono::steady_clock::now();
  for (std::int64_t i = 0; i < switches; ++i) {
    switch_fiber(other, slot);
  }
  const auto end = std::chrono::steady_clock::now();
  done = true;
  std::move(other).resume();
  return std::chrono::duration<double>(end - start).count();
}

} // namespace

double time_bare_fiber_switches(std::int64_t switches) {
  return time_switches<emulator::detail::switch_fiber_boost>(switches);
}

double time_returning_fiber_switches([[maybe_unused]] std::int64_t switches) {
#if MARSOKHOD_HAVE_RETURNING_SWITCH
  return time_switches<emulator::detail::switch_fiber_returning>(switches);
#else
  return -1.0;
#endif
}

namespace {

constexpr std::int64_t kSwitches = 1 << 20;

benchmark::Counter ns_each(double seconds, std::int64_t count) {
  return benchmark::Counter(1e9 * seconds / static_cast<double>(count));
}

void BM_BareFiberSwitch(benchmark::State& state) {
  for (auto _ : state) {
    state.SetIterationTime(time_bare_fiber_switches(kSwitches));
  }
  state.counters["ns_per_switch"] =
      benchmark::Counter(static_cast<double>(state.iterations() * kSwitches),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BareFiberSwitch)->UseManualTime()->Unit(benchmark::kMillisecond);

// Both switches in every iteration, one right after the other, so that both see the host at
// the same speed: the iteration time is the returning switch's, the ratio says how much of
// Boost's switch it costs.
void BM_ReturningAgainstBoostSwitch(benchmark::State& state) {
  if (time_returning_fiber_switches(1) < 0) {
    state.SkipWithError("this build has no returning switch");
    return;
  }
  double returning_seconds = 0.0;
  double boost_seconds = 0.0;
  for (auto _ : state) {
    const double returning = time_returning_fiber_switches(kSwitches);
    boost_seconds += time_bare_fiber_switches(kSwitches);
    returning_seconds += returning;
    state.SetIterationTime(returning);
  }
  const std::int64_t switches = state.iterations() * kSwitches;
  state.counters["ns_per_returning_switch"] = ns_each(returning_seconds, switches);
  state.counters["ns_per_boost_switch"] = ns_each(boost_seconds, switches);
  state.counters["returning_over_boost"] = benchmark::Counter(returning_seconds / boost_seconds);
}
BENCHMARK(BM_ReturningAgainstBoostSwitch)->UseManualTime()->Unit(benchmark::kMillisecond);

} // namespace
} // namespace marsokhod::benches
