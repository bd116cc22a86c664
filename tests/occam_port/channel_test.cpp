// Channels: rendezvous, data-book costs, order, deadlock reports and misuse.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::StopReason;
using emulator::Tick;
using testing::OccamRig;

// Compiled occam: each side loads its operands (ldlp 1, ldl 2, ldc 1), then in or out of a
// w-word message takes 2w+19 cycles (data book).
constexpr std::int64_t kOperands = 1 + 2 + 1;
constexpr std::int64_t kOneWordTransfer = kOperands + 2 * 1 + 19;

TEST(Channel, OutputFirstWaitsForInputAndBothPayTheDataBookCycles) {
  OccamRig rig;
  Chan<int> c("c");
  int received = 0;
  Tick writer_done = -1;
  Tick reader_done = -1;
  rig.spawn("writer", [&] {
    c << 42;
    writer_done = rig.kernel.now();
  });
  rig.spawn("reader", [&] {
    c >> received;
    reader_done = rig.kernel.now();
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, 42);
  // The writer's out ends at 25 cycles and finds no reader: it waits. The reader's in then
  // runs 25 cycles, copies and reschedules the writer, which resumes when the reader ends.
  EXPECT_EQ(reader_done, rig.cycles(2 * kOneWordTransfer));
  EXPECT_EQ(writer_done, rig.cycles(2 * kOneWordTransfer));
}

TEST(Channel, InputFirstReceivesLaterOutput) {
  OccamRig rig;
  Chan<double> c("c");
  double received = 0;
  rig.spawn(
      "reader", [&] { c >> received; });
  rig.spawn("writer", [&] { c << 2.5; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, 2.5);
  // A double is two words: 4 + 2*2+19 = 27 cycles on each side.
  EXPECT_EQ(rig.kernel.now(), rig.cycles(2 * (kOperands + 2 * 2 + 19)));
}

TEST(Channel, MessagesArriveInOrderOneAtATime) {
  OccamRig rig;
  Chan<int> c("c");
  std::vector<int> received;
  rig.spawn(
      "writer",
      [&] {
        for (int i = 0; i < 5; ++i)
          c << i * i;
      });
  rig.spawn("reader", [&] {
    for (int i = 0; i < 5; ++i) {
      int x = 0;
      c >> x;
      received.push_back(x);
    }
  });
  rig.kernel.run();
  EXPECT_EQ(received, (std::vector<int>{0, 1, 4, 9, 16}));
}

TEST(Channel, ReaderWithoutWriterIsReportedAsDeadlocked) {
  OccamRig rig;
  Chan<int> lonely("lonely");
  rig.spawn("consumer", [&] {
    int x = 0;
    lonely >> x;
  });
  const auto result = rig.kernel.run();
  ASSERT_EQ(result.reason, StopReason::deadlock);
  ASSERT_EQ(result.deadlock->processes.size(), 1U);
  EXPECT_EQ(result.deadlock->processes[0].process, "consumer");
  EXPECT_EQ(result.deadlock->processes[0].cpu, "card");
  EXPECT_EQ(result.deadlock->processes[0].kind, emulator::WaitKind::channel_input);
  EXPECT_EQ(result.deadlock->processes[0].waiting_on, "channel lonely");
}

TEST(Channel, TwoWritersOnOneChannelAreAnError) {
  OccamRig rig;
  Chan<int> c("shared");
  rig.spawn(
      "first", [&] { c << 1; });
  rig.spawn("second", [&] { c << 2; });
  EXPECT_THROW(rig.kernel.run(), std::logic_error);
}

TEST(Channel, KillingAWaitingReaderFreesTheChannel) {
  OccamRig rig;
  Chan<int> c("c");
  emulator::Process& doomed = rig.spawn("doomed", [&] {
    int x = 0;
    c >> x;
  });
  rig.kernel.run();
  rig.kernel.kill(doomed);
  int received = 0;
  rig.spawn(
      "writer", [&] { c << 7; });
  rig.spawn("reader", [&] { c >> received; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, 7);
}

TEST(Channel, EachSidePaysAtTheSpeedOfTheNodeItRunsOn) {
  // One channel used by two simulations in turn, on nodes of different speed grades that
  // may well occupy the same memory: the charge worked out for the first must not carry over.
  Chan<int> c("c");
  std::vector<std::uint64_t> serials;
  for (const Tick cycle : {Tick{33'333}, Tick{50'000}, Tick{33'333}}) {
    emulator::NodeSpec spec = testing::pc_card_node();
    spec.cpu.cycle = cycle;
    emulator::Kernel kernel;
    emulator::Node node(kernel, spec);
    serials.push_back(node.serial());
    int received = 0;
    node.spawn(
        "writer", [&] { c << 5; });
    node.spawn("reader", [&] { c >> received; });
    EXPECT_EQ(kernel.run().reason, StopReason::finished);
    EXPECT_EQ(received, 5);
    EXPECT_EQ(kernel.now(), 2 * kOneWordTransfer * cycle);
  }
  EXPECT_NE(serials[0], serials[1]);
  EXPECT_NE(serials[1], serials[2]);
  EXPECT_NE(serials[0], serials[2]);
}

TEST(Channel, UseOutsideAProcessIsAnError) {
  OccamRig rig;
  Chan<int> c("c");
  EXPECT_THROW(c << 1, std::logic_error);
}

} // namespace
} // namespace marsokhod::occam_port
