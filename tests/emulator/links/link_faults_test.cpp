// Link wire faults: dead wires, flipped data bits, lost acknowledges.
//
// Hand timing (hand_link_timing.hpp): one way, byte k starts at k x 1.1 us and arrives at
// (k + 1) x 1.1 us; its acknowledge goes 0.55 us after its start bit and ends 0.2 us later.

#include "emulator/links/hand_link_timing.hpp"
#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::emulator {
namespace {

using link_testing::hand_timing;

using link_testing::kAckDone;
using link_testing::kByte;

struct WireFaults : testing::Test {
  Kernel kernel;
  Cpu& a = kernel.add_cpu("a");
  Cpu& b = kernel.add_cpu("b");
  Link link{kernel, "a.link0", "b.link0", hand_timing()};

  /// Streams `sent` from a (end 0) to b (end 1) into `received`; records when each side ended.
  void stream(const std::vector<std::byte>& sent, std::vector<std::byte>& received) {
    kernel.spawn(a, "sender", [&] {
      link.port(0).output(sent);
      sender_done = kernel.now();
    });
    kernel.spawn(b, "receiver", [&] {
      link.port(1).input(received);
      receiver_done = kernel.now();
    });
  }

  Tick sender_done = -1;
  Tick receiver_done = -1;
};

TEST_F(WireFaults, FlippedBitArrivesInvertedAndEveryOtherByteIntact) {
  const std::vector<std::byte> sent = test_support::byte_pattern(10);
  std::vector<std::byte> received(10);
  link.flip_data_bit(0, 3, 5);
  stream(sent, received);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  std::vector<std::byte> expected = sent;
  expected[3] ^= std::byte{0x20};
  EXPECT_EQ(received, expected);
  // No parity, no retry: the timing is that of a clean transfer.
  EXPECT_EQ(receiver_done, 10 * kByte);
  EXPECT_EQ(sender_done, 9 * kByte + kAckDone);
}

TEST_F(WireFaults, FlipsCountBytesAcrossMessagesFromWhenTheyAreAsked) {
  const std::vector<std::byte> first = test_support::byte_pattern(4);
  const std::vector<std::byte> second = test_support::byte_pattern(4);
  std::vector<std::byte> at_b(8);
  link.flip_data_bit(0, 5, 0); // the second byte of the second message
  link.flip_data_bit(0, 5, 7); // the same byte, another bit
  kernel.spawn(
      a, "sender",
      [&] {
        link.port(0).output(first);
        link.port(0).output(second);
      });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(at_b); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(at_b[5], second[1] ^ std::byte{0x81});
  at_b[5] = second[1];
  EXPECT_EQ(std::vector<std::byte>(at_b.begin(), at_b.begin() + 4), first);
  EXPECT_EQ(std::vector<std::byte>(at_b.begin() + 4, at_b.end()), second);
}

TEST_F(WireFaults, StreamWithAFlipInItsMiddleKeepsTheTimesOfSteppingByteByByte) {
  const std::vector<std::byte> sent = test_support::byte_pattern(1000);
  std::vector<std::byte> received(1000);
  link.flip_data_bit(0, 500, 1);
  // Asked at 300 us, when bytes 0..272 have started (272 x 1.1 = 299.2 us): byte 283.
  kernel.schedule_at(microseconds(300), event_priority::normal,
                     [&] { link.flip_data_bit(0, 10, 6); });
  stream(sent, received);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  std::vector<std::byte> expected = sent;
  expected[500] ^= std::byte{0x02};
  expected[283] ^= std::byte{0x40};
  EXPECT_EQ(received, expected);
  // The same times as the clean stream, which the fast path jumps and stepping would give.
  EXPECT_EQ(receiver_done, 1000 * kByte);
  EXPECT_EQ(sender_done, 999 * kByte + kAckDone);
}

TEST_F(WireFaults, DeadWireCarriesNoneOfItsEndsData) {
  link.set_wire_dead(1, true);
  const std::vector<std::byte> sent = test_support::byte_pattern(4);
  std::vector<std::byte> at_a(4, std::byte{0});
  kernel.spawn(
      b, "sender", [&] { link.port(1).output(sent); });
  kernel.spawn(a, "receiver", [&] { link.port(0).input(at_a); });
  const RunResult result = kernel.run();
  EXPECT_EQ(result.reason, StopReason::deadlock);
  EXPECT_EQ(at_a, std::vector<std::byte>(4, std::byte{0}));
  EXPECT_EQ(link.port(1).describe(), "link b.link0, output: 4 of 4 bytes unacknowledged");
  EXPECT_EQ(kernel.now(), kByte); // the first packet, lost, was the last thing on the wire
}

TEST_F(WireFaults, DeadWireBackStallsTheOutputAfterExactlyOneByte) {
  link.set_wire_dead(1, true);
  const std::vector<std::byte> sent = test_support::byte_pattern(10);
  std::vector<std::byte> received(10, std::byte{0});
  stream(sent, received);
  const RunResult result = kernel.run();
  EXPECT_EQ(result.reason, StopReason::deadlock);
  // Byte 0 arrives at 1.1 us; its acknowledge goes on the dead wire, so byte 1 never starts.
  std::vector<std::byte> expected(10, std::byte{0});
  expected[0] = sent[0];
  EXPECT_EQ(received, expected);
  EXPECT_EQ(kernel.now(), kByte);
  EXPECT_EQ(link.port(0).describe(), "link a.link0, output: 10 of 10 bytes unacknowledged");
  EXPECT_EQ(link.port(1).describe(), "link b.link0, input: 9 of 10 bytes still to come");
  ASSERT_TRUE(result.deadlock.has_value());
  EXPECT_EQ(result.deadlock->processes.size(), 2U);
}

TEST_F(WireFaults, TransientDeadWireLosesWhatWentMeanwhileAndLetsLaterTransfersThrough) {
  const std::vector<std::byte> lost = test_support::byte_pattern(4);
  const std::vector<std::byte> later = test_support::byte_pattern(6);
  std::vector<std::byte> received(6);
  LinkTransferResult first;
  Tick second_done = -1;
  link.set_wire_dead(0, true);
  kernel.schedule_at(microseconds(10), event_priority::normal,
                     [&] { link.set_wire_dead(0, false); });
  // The first byte went at 0 on the dead wire: mending it does not bring the acknowledge back,
  // the sender waits until its output is reset at 12 us, then sends again.
  kernel.schedule_at(microseconds(12), event_priority::normal, [&] { link.port(0).reset(); });
  kernel.spawn(a, "sender", [&] {
    first = link.port(0).output(lost);
    link.port(0).output(later);
    second_done = kernel.now();
  });
  kernel.spawn(b, "receiver", [&] {
    link.port(1).input(received);
    receiver_done = kernel.now();
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.bytes, 0U);
  EXPECT_EQ(received, later);
  EXPECT_EQ(receiver_done, microseconds(12) + 6 * kByte);
  EXPECT_EQ(second_done, microseconds(12) + 5 * kByte + kAckDone);
}

TEST_F(WireFaults, LostAcknowledgeLeavesTheOutputWaitingForever) {
  const std::vector<std::byte> sent = test_support::byte_pattern(1000);
  std::vector<std::byte> received(1000);
  // At 500 us the acknowledge of byte 454 has started (454 x 1.1 + 0.55 = 499.95 us): the
  // next one, byte 455's at 501.05 us, is lost. Byte 455 itself (from 500.5 us) arrives.
  kernel.schedule_at(microseconds(500), event_priority::normal, [&] { link.lose_acknowledge(1); });
  stream(sent, received);
  const RunResult result = kernel.run();
  EXPECT_EQ(result.reason, StopReason::deadlock);
  EXPECT_EQ(kernel.now(), 456 * kByte);
  EXPECT_EQ(sender_done, -1);
  EXPECT_EQ(link.port(0).describe(), "link a.link0, output: 545 of 1000 bytes unacknowledged");
  EXPECT_EQ(link.port(1).describe(), "link b.link0, input: 544 of 1000 bytes still to come");
  EXPECT_TRUE(std::equal(sent.begin(), sent.begin() + 456, received.begin()));
}

TEST_F(WireFaults, OnlyTheNextAcknowledgeIsLost) {
  // Lost before anything is sent: byte 0's acknowledge. The sender then waits; its reset at
  // 5 us lets a second message through with every acknowledge.
  link.lose_acknowledge(1);
  const std::vector<std::byte> sent = test_support::byte_pattern(3);
  std::vector<std::byte> received(3);
  LinkTransferResult first;
  LinkTransferResult second;
  kernel.schedule_at(microseconds(5), event_priority::normal, [&] { link.port(0).reset_output(); });
  kernel.spawn(
      a, "sender",
      [&] {
        first = link.port(0).output(std::span(sent).first(1));
        second = link.port(0).output(std::span(sent).subspan(1));
        sender_done = kernel.now();
      });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_FALSE(first.complete);
  EXPECT_TRUE(second.complete);
  EXPECT_EQ(second.bytes, 2U);
  EXPECT_EQ(received, sent);
  EXPECT_EQ(sender_done, microseconds(5) + kByte + kAckDone);
}

/// Keeps the instants a run traces, as "track @time: name".
class InstantLog : public TraceSink {
public:
  TrackId track(std::string_view group, std::string_view name) override {
    const std::string key = std::string(group) + " " + std::string(name);
    const auto found = ids_.try_emplace(key, static_cast<TrackId>(names_.size()));
    if (found.second)
      names_.push_back(key);
    return found.first->second;
  }
  void begin_slice(TrackId, Tick, std::string_view) override {}
  void end_slice(TrackId, Tick) override {}
  void counter(TrackId, Tick, std::string_view, std::int64_t) override {}
  void instant(TrackId track, Tick at, std::string_view name, std::string_view) override {
    instants.push_back(names_[track] + " @" + std::to_string(at) + ": " + std::string(name));
  }
  void flow_begin(TrackId, Tick, std::uint64_t) override {}
  void flow_end(TrackId, Tick, std::uint64_t) override {}

  std::vector<std::string> instants;

private:
  std::map<std::string, TrackId> ids_;
  std::vector<std::string> names_;
};

TEST_F(WireFaults, EachFaultAndResetMarksTheLinksTrackWhenItHappens) {
  InstantLog log;
  kernel.set_trace(&log);
  const std::vector<std::byte> sent = test_support::byte_pattern(3);
  std::vector<std::byte> received(3);
  link.flip_data_bit(0, 1, 0);
  // Byte 2's acknowledge, from 2.75 us, is the next one after 2.5 us.
  kernel.schedule_at(
      2'500'000, event_priority::normal, [&] { link.lose_acknowledge(1); });
  kernel.schedule_at(
      microseconds(10), event_priority::normal, [&] { link.port(0).reset_output(); });
  kernel.schedule_at(
      microseconds(11), event_priority::normal, [&] { link.set_wire_dead(1, true); });
  kernel.schedule_at(microseconds(12), event_priority::normal,
                     [&] { link.set_wire_dead(1, false); });
  stream(sent, received);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(log.instants, (std::vector<std::string>{
                              "a link0 out @1100000: bit flipped",
                              "b link0 out @2750000: acknowledge lost",
                              "a link0 out @10000000: resetch",
                              "b link0 out @11000000: wire dead",
                              "b link0 out @12000000: wire mended",
                          }));
}

TEST(WireFaultArguments, EndsAndBitsOutOfRangeAreRefused) {
  Kernel kernel;
  Link link{kernel, "a.link0", "b.link0", hand_timing()};
  EXPECT_THROW(link.set_wire_dead(2, true), std::out_of_range);
  EXPECT_THROW(link.lose_acknowledge(-1), std::out_of_range);
  EXPECT_THROW(link.flip_data_bit(0, 0, 8), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::emulator
