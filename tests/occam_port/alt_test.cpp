// ALT and PRI ALT, index form, and TIMER: guard order, preconditions, SKIP and timeouts.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::Priority;
using emulator::StopReason;
using emulator::Tick;
using testing::OccamRig;

TEST(Alt, PriAltTakesTheFirstReadyGuardInTextualOrder) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  std::vector<std::size_t> chosen;
  std::vector<int> values;
  rig.spawn(
      "writer a", [&] { a << 1; });
  rig.spawn("writer b", [&] { b << 2; });
  rig.spawn("alting", [&] {
    // Both writers are committed by now: the first guard listed wins, whichever order.
    const std::size_t first = pri_alt({input(b), input(a)});
    chosen.push_back(first);
    int x = 0;
    (first == 0 ? b : a) >> x;
    values.push_back(x);
    const std::size_t second = pri_alt({input(b), input(a)});
    chosen.push_back(second);
    (second == 0 ? b : a) >> x;
    values.push_back(x);
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(chosen, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(values, (std::vector<int>{2, 1}));
}

TEST(Alt, FalsePreconditionHidesAReadyChannel) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  std::size_t chosen = 99;
  rig.spawn(
      "writer a", [&] { a << 1; });
  rig.spawn("writer b", [&] { b << 2; });
  rig.spawn("alting", [&] {
    chosen = pri_alt({when(false, input(a)), input(b)});
    int x = 0;
    b >> x;
    a >> x;
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(chosen, 1U);
}

TEST(Alt, SkipIsTakenOnlyWhenNoEarlierGuardIsReady) {
  OccamRig rig;
  Chan<int> a("a");
  std::vector<std::size_t> chosen;
  rig.spawn(
      "alting",
      [&] {
        chosen.push_back(pri_alt({input(a), skip()})); // a has no writer yet
        Timer tim;
        tim.wait_after(tim.read()); // the writer runs and commits meanwhile
        chosen.push_back(pri_alt({input(a), skip()}));
        int x = 0;
        a >> x;
        chosen.push_back(pri_alt({input(a), when(false, skip()), skip()}));
      });
  rig.spawn("writer", [&] { a << 5; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(chosen, (std::vector<std::size_t>{1, 0, 2}));
}

TEST(Alt, TimerGuardFiresWhenTheClockPassesItsTime) {
  OccamRig rig;
  Chan<int> never("never");
  Timer tim;
  std::size_t chosen = 99;
  std::int32_t clock_after = 0;
  Tick selected_at = -1;
  rig.spawn(
      "alting",
      [&] {
        const std::int32_t t0 = tim.read(); // ldtimer: 2 cycles, reads 0
        chosen = pri_alt({input(never), after(tim, t0 + 100)});
        selected_at = rig.kernel.now();
        clock_after = tim.read();
      },
      Priority::high);
  rig.kernel.run();
  EXPECT_EQ(chosen, 1U);
  // occam: AFTER t holds once the clock reads t+1; the high-priority clock ticks every 1 us.
  // Then the disables run: disc 8 + dist 23 + altend 4 cycles (data book).
  EXPECT_EQ(selected_at, emulator::microseconds(101) + rig.cycles(8 + 23 + 4));
  // The second ldtimer (2 cycles) reads the clock after those 37 cycles (1.23 us) too.
  EXPECT_EQ(clock_after,
            (emulator::microseconds(101) + rig.cycles(8 + 23 + 4 + 2)) / emulator::kMicrosecond);
}

TEST(Alt, LowPriorityTimerGuardUsesThe64MicrosecondClock) {
  OccamRig rig;
  Timer tim;
  Tick selected_at = -1;
  rig.spawn("alting", [&] {
    const std::int32_t t0 = tim.read();
    pri_alt({after(tim, t0 + 2)});
    selected_at = rig.kernel.now();
  });
  rig.kernel.run();
  // Clock 3 is reached at 3 x 64 us; then dist 23 + altend 4 cycles.
  EXPECT_EQ(selected_at, emulator::microseconds(3 * 64) + rig.cycles(23 + 4));
}

TEST(Alt, ReadyChannelBeatsALaterListedTimerThatHasNotFired) {
  OccamRig rig;
  Chan<int> a("a");
  Timer tim;
  std::size_t chosen = 99;
  rig.spawn("writer", [&] { a << 1; });
  rig.spawn("alting", [&] {
    chosen = pri_alt({after(tim, tim.read() + 1000), input(a)});
    int x = 0;
    a >> x;
  });
  rig.kernel.run();
  EXPECT_EQ(chosen, 1U);
}

TEST(Alt, WaitingAltIsWokenByALaterOutput) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  std::size_t chosen = 99;
  int value = 0;
  rig.spawn("alting", [&] {
    chosen = pri_alt({input(a), input(b)});
    (chosen == 0 ? a : b) >> value;
  });
  rig.spawn("writer", [&] {
    rig.node.compute_cycles(5000);
    b << 77;
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(chosen, 1U);
  EXPECT_EQ(value, 77);
}

TEST(Alt, AltWithNoEnabledGuardStopsAndIsReported) {
  OccamRig rig;
  Chan<int> a("a");
  rig.spawn("stuck", [&] { pri_alt({when(false, input(a)), when(false, skip())}); });
  const auto result = rig.kernel.run();
  ASSERT_EQ(result.reason, StopReason::deadlock);
  ASSERT_EQ(result.deadlock->processes.size(), 1U);
  EXPECT_EQ(result.deadlock->processes[0].kind, emulator::WaitKind::alt);
  EXPECT_EQ(result.deadlock->processes[0].waiting_on, "ALT {FALSE & channel a, FALSE & SKIP}");
}

TEST(Alt, KillingAWaitingAltLeavesItsChannelsUsable) {
  OccamRig rig;
  Chan<int> a("a");
  emulator::Process& alting = rig.spawn("alting", [&] { pri_alt({input(a)}); });
  rig.kernel.run();
  rig.kernel.kill(alting);
  int received = 0;
  rig.spawn(
      "writer", [&] { a << 3; });
  rig.spawn("reader", [&] { a >> received; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, 3);
}

TEST(Timer, ClockComparisonWrapsAround) {
  EXPECT_TRUE(is_after(1, 0));
  EXPECT_FALSE(is_after(0, 0));
  EXPECT_FALSE(is_after(0, 1));
  // Past the 32-bit wrap the most negative value is after the most positive one.
  EXPECT_TRUE(is_after(INT32_MIN, INT32_MAX));
  EXPECT_FALSE(is_after(INT32_MAX, INT32_MIN));
}

TEST(Timer, TimeAfterCountsTicksAcrossTheWrap) {
  const Tick period = emulator::kMicrosecond;
  const Tick near_wrap = (Tick{1} << 32) * period - 3 * period; // clock reads -3 (0xFFFFFFFD)
  EXPECT_EQ(Timer::clock_at(near_wrap, period), -3);
  // AFTER 1 holds when the clock reads 2, five ticks later.
  EXPECT_EQ(Timer::time_after(1, near_wrap, period), near_wrap + 5 * period);
  // Already after: no wait.
  EXPECT_EQ(Timer::time_after(-10, near_wrap, period), near_wrap);
}

TEST(Timer, WaitAfterResumesOnTheTick) {
  OccamRig rig;
  Timer tim;
  Tick resumed = -1;
  rig.spawn(
      "sleeper",
      [&] {
        tim.wait_after(41);
        resumed = rig.kernel.now();
      },
      Priority::high);
  rig.kernel.run();
  EXPECT_EQ(resumed, emulator::microseconds(42));
}

} // namespace
} // namespace marsokhod::occam_port
