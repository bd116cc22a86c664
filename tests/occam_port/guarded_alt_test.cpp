// Handler ALT: the selected guard's input and handler run, with the index form's semantics.

#include "occam_port/link_rig.hpp"
#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::Priority;
using emulator::StopReason;
using emulator::Tick;
using testing::OccamRig;
using testing::TwoModules;

/// Which handler ran, and with what value.
struct Fired {
  std::vector<std::pair<std::string, int>> calls;
  auto record(std::string name) {
    return [this, name = std::move(name)](int x) { calls.emplace_back(name, x); };
  }
  auto record_no_value(std::string name) {
    return [this, name = std::move(name)] { calls.emplace_back(name, 0); };
  }
};

using Calls = std::vector<std::pair<std::string, int>>;

TEST(GuardedAlt, RunsTheSelectedGuardsHandlerWithTheValueItRead) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  Fired fired;
  std::vector<std::size_t> chosen;
  rig.spawn(
      "writer a", [&] { a << 1; });
  rig.spawn("writer b", [&] { b << 2; });
  rig.spawn("alting", [&] {
    // Both writers are committed: b is listed first and wins, then only a is left.
    for (int i = 0; i < 2; ++i)
      chosen.push_back(pri_alt(on_input(b, fired.record("b")), on_input(a, fired.record("a"))));
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(chosen, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(fired.calls, (Calls{{"b", 2}, {"a", 1}}));
}

TEST(GuardedAlt, GuardsOnInputEndsReadThroughThoseEnds) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  std::vector<int> got;
  rig.spawn(
      "writer", [out = b.out()] { out << 5; });
  rig.spawn("alting", [&, in_a = a.in(), in_b = b.in()] {
    alt(on_input(in_a, [&](int x) { got.push_back(-x); }),
        on_input(in_b, [&](const int& x) { got.push_back(x); }));
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(got, (std::vector<int>{5}));
}

TEST(GuardedAlt, FalsePreconditionExcludesAReadyGuard) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  Fired fired;
  int left_on_a = 0;
  rig.spawn(
      "writer a", [&] { a << 1; });
  rig.spawn("writer b", [&] { b << 2; });
  rig.spawn("alting", [&] {
    pri_alt(when(false, on_input(a, fired.record("a"))), on_input(b, fired.record("b")));
    a >> left_on_a; // the excluded guard's input was not performed
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"b", 2}}));
  EXPECT_EQ(left_on_a, 1);
}

TEST(GuardedAlt, TrueConditionKeepsTheGuard) {
  OccamRig rig;
  Chan<int> a("a");
  Fired fired;
  rig.spawn(
      "writer", [&] { a << 3; });
  rig.spawn("alting", [&] {
    pri_alt(when(true, on_input(a, fired.record("a"))), on_skip(fired.record_no_value("skip")));
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"a", 3}}));
}

TEST(GuardedAlt, TimeoutGuardFiresWhenTheClockPassesItsTime) {
  OccamRig rig;
  Chan<int> never("never");
  Timer tim;
  Fired fired;
  Tick fired_at = -1;
  rig.spawn(
      "alting",
      [&] {
        const std::int32_t t0 = tim.read(); // ldtimer: 2 cycles, reads 0
        pri_alt(on_input(never, fired.record("never")), on_after(tim, t0 + 100, [&] {
                  fired_at = rig.kernel.now();
                  fired.calls.emplace_back("timeout", 0);
                }));
      },
      Priority::high);
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"timeout", 0}}));
  // AFTER t holds once the 1 us high-priority clock reads t+1; then the disables run: disc 8 +
  // dist 23 + altend 4 cycles (data book), and the handler runs right after.
  EXPECT_EQ(fired_at, emulator::microseconds(101) + rig.cycles(8 + 23 + 4));
}

TEST(GuardedAlt, SkipRunsOnlyWhenNoEarlierGuardIsReady) {
  OccamRig rig;
  Chan<int> a("a");
  Fired fired;
  rig.spawn(
      "alting",
      [&] {
        Timer tim;
        pri_alt(on_input(a, fired.record("a")),
                on_skip(fired.record_no_value("skip"))); // no writer
        tim.wait_after(tim.read());                      // the writer runs and commits meanwhile
        pri_alt(on_input(a, fired.record("a")), on_skip(fired.record_no_value("skip")));
      });
  rig.spawn("writer", [&] { a << 5; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"skip", 0}, {"a", 5}}));
}

TEST(GuardedAlt, PriAltServesReadyGuardsInTheOrderListed) {
  OccamRig rig;
  Chan<int> a("a"), b("b"), c("c");
  Fired fired;
  rig.spawn(
      "writer a", [&] { a << 1; });
  rig.spawn(
      "writer b", [&] { b << 2; });
  rig.spawn("writer c", [&] { c << 3; });
  rig.spawn("alting", [&] {
    // All three are committed before the first ALT; each ALT takes the first still ready.
    for (int i = 0; i < 3; ++i)
      pri_alt(on_input(c, fired.record("c")), on_input(a, fired.record("a")),
              on_input(b, fired.record("b")), on_skip(fired.record_no_value("skip")));
    pri_alt(on_input(c, fired.record("c")), on_input(a, fired.record("a")),
            on_input(b, fired.record("b")), on_skip(fired.record_no_value("skip")));
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"c", 3}, {"a", 1}, {"b", 2}, {"skip", 0}}));
}

TEST(GuardedAlt, WaitingAltIsWokenByALaterOutputAndChargedAsTheIndexForm) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  Fired fired;
  Tick handled_at = -1;
  Tick writer_done = -1;
  rig.spawn("alting", [&] {
    pri_alt(on_input(a, fired.record("a")), on_input(b, [&](int x) {
              handled_at = rig.kernel.now();
              fired.calls.emplace_back("b", x);
            }));
  });
  rig.spawn("writer", [&] {
    b << 77;
    writer_done = rig.kernel.now();
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"b", 77}}));
  // Data book: the ALT runs alt 2 + enbc 5 + enbc 5 (neither ready) + altwt 17 and waits at
  // 29 cycles; the writer's out (4 + 21) commits at 54 and wakes it; the disables take
  // altend 4 + disc 8 + disc 8, then the input 4 + 21 releases the writer at 99 cycles.
  EXPECT_EQ(handled_at, rig.cycles(99));
  EXPECT_EQ(writer_done, rig.cycles(99));
}

TEST(GuardedAlt, AltOnALinkChannelRunsTheHandlerWithTheMessage) {
  TwoModules rig;
  Chan<int> c("m0->m1");
  rig.wire(c, rig.m0, rig.m1);
  Fired fired;
  rig.m0.spawn("sender", [&, out = c.out()] {
    compute(emulator::Instruction::mul, 100);
    out << 1234;
  });
  rig.m1.spawn("alting", [&, in = c.in()] {
    Timer tim;
    pri_alt(on_input(in, fired.record("link")),
            on_after(tim, tim.read() + 1000, fired.record_no_value("timeout")));
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired.calls, (Calls{{"link", 1234}}));
}

} // namespace
} // namespace marsokhod::occam_port
