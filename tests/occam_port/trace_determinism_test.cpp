// Two runs of the same scenario write byte-identical traces.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/emulator/trace/chrome_trace.hpp"
#include "marsokhod/occam_port/commstime.hpp"
#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace marsokhod::occam_port {
namespace {

/// Commstime plus a PRI PAR with a timer-guarded ALT, traced into a string.
std::string traced_run() {
  std::ostringstream out;
  {
    emulator::ChromeTraceWriter writer(out);
    emulator::Kernel kernel;
    kernel.set_trace(&writer);
    emulator::Node node(kernel, testing::pc_card_node());
    CommstimeOptions options;
    options.loops = 50;
    CommstimeResult result;
    spawn_commstime(node, options, result);
    node.spawn("watchdog", [] {
      Chan<int> heartbeat("heartbeat");
      Timer tim;
      pri_par(
          [&] {
            int beats = 0;
            while (beats < 3) { // timeouts in between: each beat takes ~127 us of mul
              const std::size_t k = pri_alt({input(heartbeat), after(tim, tim.read() + 20)});
              int beat = 0;
              if (k == 0) {
                heartbeat >> beat;
                ++beats;
              }
            }
          },
          [&] {
            for (int i = 0; i < 3; ++i) {
              compute(emulator::Instruction::mul, 100);
              heartbeat << i;
            }
          });
    });
    EXPECT_EQ(kernel.run().reason, emulator::StopReason::finished);
    writer.close();
  }
  return out.str();
}

TEST(TraceDeterminism, TwoRunsOfTheSameScenarioGiveByteIdenticalTraces) {
  const std::string first = traced_run();
  const std::string second = traced_run();
  EXPECT_EQ(first, second);
  // The trace shows the processes running: slices named after them on the node's cpu track.
  EXPECT_NE(first.find("commstime.1"), std::string::npos);
  EXPECT_NE(first.find("watchdog.0"), std::string::npos);
  EXPECT_GT(first.size(), 10'000U);
}

} // namespace
} // namespace marsokhod::occam_port
