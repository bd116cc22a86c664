// resetch on a link port: hung transfers released, cut short, and the peer left as it was.
//
// Hand timing (hand_link_timing.hpp): one way, byte k starts at k x 1.1 us and arrives at
// (k + 1) x 1.1 us; its acknowledge goes 0.55 us after its start bit and ends 0.2 us later.

#include "emulator/links/hand_link_timing.hpp"
#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace marsokhod::emulator {
namespace {

using link_testing::hand_timing;

using link_testing::kAckDone;
using link_testing::kByte;

struct LinkReset : testing::Test {
  Kernel kernel;
  Cpu& a = kernel.add_cpu("a");
  Cpu& b = kernel.add_cpu("b");
  Link link{kernel, "a.link0", "b.link0", hand_timing()};
  const std::vector<std::byte> sent = test_support::byte_pattern(1000);
  std::vector<std::byte> received = std::vector<std::byte>(1000);

  /// 1000 bytes from a to b whose byte 455's acknowledge is lost: at 500 us byte 454's has
  /// started (499.95 us), so the next, at 501.05 us, goes. Bytes 0..454 are acknowledged,
  /// 0..455 arrive (the last at 501.6 us).
  void lose_an_acknowledge_mid_stream() {
    kernel.schedule_at(
        microseconds(500), event_priority::normal, [&] { link.lose_acknowledge(1); });
  }
};

TEST_F(LinkReset, ReleasesAnOutputHungOnALostAcknowledgeAtOnceAndCutShort) {
  lose_an_acknowledge_mid_stream();
  LinkTransferResult result;
  Tick resumed = -1;
  kernel.spawn(a, "sender", [&] {
    result = link.port(0).output(sent);
    resumed = kernel.now();
  });
  // The OrFail pattern: a process of the same node gives the output 600 us, then resets it.
  kernel.spawn(
      a, "watchdog",
      [&] {
        kernel.consume(microseconds(600));
        EXPECT_TRUE(link.port(0).reset_output());
      });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  const RunResult run = kernel.run();
  EXPECT_EQ(resumed, microseconds(600));
  EXPECT_FALSE(result.complete);
  EXPECT_FALSE(result);
  EXPECT_EQ(result.bytes, 455U);
  EXPECT_EQ(link.port(0).bytes_sent(), 455U);
  EXPECT_EQ(link.port(0).output_busy_time(), microseconds(600));
  // The peer is not reset: its input still waits for the rest.
  EXPECT_EQ(run.reason, StopReason::deadlock);
  ASSERT_TRUE(run.deadlock.has_value());
  ASSERT_EQ(run.deadlock->processes.size(), 1U);
  EXPECT_EQ(run.deadlock->processes[0].process, "receiver");
  EXPECT_EQ(link.port(1).describe(), "link b.link0, input: 544 of 1000 bytes still to come");
}

TEST_F(LinkReset, WithoutThePeersResetItsInputTakesTheNextMessage) {
  lose_an_acknowledge_mid_stream();
  const std::vector<std::byte> next = test_support::byte_pattern(8, 100);
  kernel.spawn(
      a, "sender",
      [&] {
        link.port(0).output(sent);
        link.port(0).output(next);
      });
  kernel.schedule_at(
      microseconds(600), event_priority::normal, [&] { link.port(0).reset(); });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  EXPECT_EQ(kernel.run().reason, StopReason::deadlock);
  // Links carry bytes, not messages: the 8 bytes land behind byte 455 of the old input.
  EXPECT_TRUE(std::equal(next.begin(), next.end(), received.begin() + 456));
  EXPECT_EQ(link.port(1).describe(), "link b.link0, input: 536 of 1000 bytes still to come");
  EXPECT_EQ(kernel.now(), microseconds(600) + 8 * kByte);
}

TEST_F(LinkReset, BothEndsResetCarryTheNextMessageWhole) {
  lose_an_acknowledge_mid_stream();
  const std::vector<std::byte> next = test_support::byte_pattern(8, 100);
  std::vector<std::byte> next_received(8);
  LinkTransferResult cut_input;
  Tick sender_done = -1;
  Tick receiver_done = -1;
  kernel.spawn(a, "sender", [&] {
    link.port(0).output(sent);
    kernel.consume(microseconds(200)); // resumed at 600 us: sends again at 800 us
    link.port(0).output(next);
    sender_done = kernel.now();
  });
  kernel.spawn(
      b, "receiver",
      [&] {
        cut_input = link.port(1).input(received);
        link.port(1).input(next_received);
        receiver_done = kernel.now();
      });
  kernel.schedule_at(
      microseconds(600), event_priority::normal, [&] { link.port(0).reset(); });
  kernel.schedule_at(microseconds(700), event_priority::normal, [&] { link.port(1).reset(); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_FALSE(cut_input.complete);
  EXPECT_EQ(cut_input.bytes, 456U);
  EXPECT_EQ(next_received, next);
  EXPECT_EQ(receiver_done, microseconds(800) + 8 * kByte);
  EXPECT_EQ(sender_done, microseconds(800) + 7 * kByte + kAckDone);
}

TEST_F(LinkReset, CutsAnInputShortWithTheBytesStored) {
  const std::vector<std::byte> four = test_support::byte_pattern(4);
  LinkTransferResult result;
  Tick resumed = -1;
  Tick sender_done = -1;
  kernel.spawn(a, "sender", [&] {
    EXPECT_TRUE(link.port(0).output(four));
    sender_done = kernel.now();
  });
  kernel.spawn(
      b, "receiver",
      [&] {
        result = link.port(1).input(std::span(received).first(10));
        resumed = kernel.now();
      });
  kernel.schedule_at(microseconds(20), event_priority::normal,
                     [&] { EXPECT_TRUE(link.port(1).reset_input()); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(sender_done, 3 * kByte + kAckDone);
  EXPECT_EQ(resumed, microseconds(20));
  EXPECT_FALSE(result.complete);
  EXPECT_EQ(result.bytes, 4U);
  EXPECT_TRUE(std::equal(four.begin(), four.end(), received.begin()));
}

TEST_F(LinkReset, InputResetDropsTheByteItHadTakenOnTheWire) {
  // Byte 0 is on the wire from 0 to 1.1 us, taken at its start bit, its acknowledge due at
  // 0.55 us; the reset at 0.3 us forgets that acknowledge and drops the byte on arrival.
  LinkTransferResult result;
  kernel.spawn(
      a, "sender", [&] { link.port(0).output(std::span(sent).first(10)); });
  kernel.spawn(
      b, "receiver", [&] { result = link.port(1).input(std::span(received).first(10)); });
  kernel.schedule_at(300'000, event_priority::normal, [&] { link.port(1).reset_input(); });
  EXPECT_EQ(kernel.run().reason, StopReason::deadlock);
  EXPECT_EQ(result.bytes, 0U);
  EXPECT_FALSE(link.port(1).byte_waiting());
  EXPECT_EQ(received[0], std::byte{0});
  EXPECT_EQ(link.port(0).describe(), "link a.link0, output: 10 of 10 bytes unacknowledged");
  EXPECT_EQ(kernel.now(), kByte);
}

TEST_F(LinkReset, InputResetForgetsAByteWaitingUnacknowledged) {
  LinkTransferResult result;
  kernel.spawn(a, "sender", [&] { result = link.port(0).output(std::span(sent).first(2)); });
  bool waiting_before = false;
  kernel.schedule_at(
      microseconds(5), event_priority::normal,
      [&] {
        waiting_before = link.port(1).byte_waiting();
        EXPECT_FALSE(link.port(1).reset_input()); // no input was in progress
      });
  kernel.schedule_at(microseconds(10), event_priority::normal, [&] { link.port(0).reset(); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_TRUE(waiting_before);
  EXPECT_FALSE(link.port(1).byte_waiting());
  // Byte 0 was never acknowledged: the sender waited until its own reset.
  EXPECT_FALSE(result.complete);
  EXPECT_EQ(result.bytes, 0U);
  EXPECT_EQ(kernel.now(), microseconds(10));
}

TEST_F(LinkReset, OfAnIdlePortChangesNothing) {
  EXPECT_FALSE(link.port(0).reset());
  EXPECT_FALSE(link.port(1).reset());
  Tick receiver_done = -1;
  LinkTransferResult result;
  kernel.spawn(a, "sender", [&] { result = link.port(0).output(std::span(sent).first(10)); });
  kernel.spawn(b, "receiver", [&] {
    link.port(1).input(std::span(received).first(10));
    receiver_done = kernel.now();
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_TRUE(result.complete);
  EXPECT_EQ(result.bytes, 10U);
  EXPECT_EQ(receiver_done, 10 * kByte);
}

} // namespace
} // namespace marsokhod::emulator
