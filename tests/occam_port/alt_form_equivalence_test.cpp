// Handler ALT and index ALT plus read: same choices, simulated times and traces.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/emulator/trace/chrome_trace.hpp"
#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::Priority;
using emulator::StopReason;
using emulator::Tick;
using testing::OccamRig;

enum class Form { index, handlers };

constexpr int kTimeout = -1;
constexpr int kEnd = -2;

/// The multiplexer of docs/emulator.md: whatever arrives first on in0 or in1 (in0 first when
/// both are ready) goes to out, or -1 when 100 ticks pass with neither; stops after `values`.
void mux(Form form, ChanIn<int> in0, ChanIn<int> in1, ChanOut<int> out, int values) {
  Timer tim;
  for (int received = 0; received < values;) {
    const std::int32_t t = tim.read();
    if (form == Form::handlers) {
      const auto pass = [&](int x) {
        out << x;
        ++received;
      };
      pri_alt(on_input(in0, pass), on_input(in1, pass),
              on_after(tim, t + 100, [&] { out << kTimeout; }));
      continue;
    }
    int x = 0;
    switch (pri_alt({input(in0), input(in1), after(tim, t + 100)})) {
    case 0:
      in0 >> x;
      out << x;
      ++received;
      break;
    case 1:
      in1 >> x;
      out << x;
      ++received;
      break;
    default:
      out << kTimeout;
      break;
    }
  }
  out << kEnd;
}

struct Outcome {
  std::vector<int> received;
  Tick end = -1;
  std::string trace;
};

/// Two producers at different paces into the multiplexer, traced.
Outcome run_mux(Form form) {
  Outcome outcome;
  std::ostringstream trace;
  {
    emulator::ChromeTraceWriter writer(trace);
    OccamRig rig;
    rig.kernel.set_trace(&writer);
    Chan<int> in0("in0"), in1("in1"), out("out");
    rig.spawn(
        "fast",
        [out = in0.out()] {
          for (int i = 0; i < 4; ++i) {
            compute(emulator::Instruction::mul, 40); // 1520 cycles, about 51 us
            out << i;
          }
        });
    rig.spawn(
        "slow",
        [out = in1.out()] {
          for (int i = 0; i < 3; ++i) {
            compute(emulator::Instruction::mul, 150); // about 190 us: the mux times out between
            out << 100 + i;
          }
        });
    rig.spawn(
        "mux", [&, form] { mux(form, in0, in1, out, 7); }, Priority::high);
    rig.spawn("sink", [&, in = out.in()] {
      for (int x = 0; x != kEnd;) {
        in >> x;
        outcome.received.push_back(x);
      }
    });
    EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
    outcome.end = rig.kernel.now();
    writer.close();
  }
  outcome.trace = trace.str();
  return outcome;
}

TEST(AltFormEquivalence, HandlerAndIndexFormsGiveTheSameSimulatedTimesAndTraces) {
  const Outcome index = run_mux(Form::index);
  const Outcome handlers = run_mux(Form::handlers);
  EXPECT_EQ(handlers.received, index.received);
  EXPECT_EQ(handlers.end, index.end);
  EXPECT_EQ(handlers.trace, index.trace);
  // The run exercised every guard: all seven values (fast's in order, slow's in order) and at
  // least one timeout.
  std::vector<int> fast;
  std::vector<int> slow;
  int timeouts = 0;
  for (const int x : handlers.received) {
    if (x == kEnd)
      continue;
    if (x == kTimeout) {
      ++timeouts;
      continue;
    }
    (x >= 100 ? slow : fast).push_back(x);
  }
  EXPECT_EQ(fast, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(slow, (std::vector<int>{100, 101, 102}));
  EXPECT_GE(timeouts, 1);
  EXPECT_EQ(handlers.received.back(), kEnd);
  EXPECT_GT(handlers.trace.size(), 1'000U);
}

/// A writer committed before the ALT starts; returns when the ALTing process had its value.
Tick ready_alt_done(Form form) {
  OccamRig rig;
  Chan<int> a("a"), b("b");
  Tick done = -1;
  int value = 0;
  rig.spawn(
      "writer", [&] { a << 7; });
  rig.spawn("alting", [&] {
    if (form == Form::handlers) {
      pri_alt(on_input(b, [&](int x) { value = -x; }), on_input(a, [&](int x) { value = x; }));
    } else if (pri_alt({input(b), input(a)}) == 0) {
      b >> value;
    } else {
      a >> value;
    }
    done = rig.kernel.now();
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(value, 7);
  return done;
}

TEST(AltFormEquivalence, BothFormsChargeTheEnablesDisablesAndTheInput) {
  // Data book: the writer's out (ldlp 1 + ldl 2 + ldc 1, then 2+19) ends at 25 cycles and
  // waits. The ALT: alt 2, enbc 5 (b, no writer), enbc 7 (a, ready), altwt 5 (ready), altend 4,
  // disc 8 twice, then the input on a: 4 + 21. 25 + 14 + 5 + 20 + 25 = 89 cycles.
  OccamRig rig;
  EXPECT_EQ(ready_alt_done(Form::index), rig.cycles(89));
  EXPECT_EQ(ready_alt_done(Form::handlers), rig.cycles(89));
}

} // namespace
} // namespace marsokhod::occam_port
