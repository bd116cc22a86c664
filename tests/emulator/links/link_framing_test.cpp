// Link handshake timing: data and acknowledge packets at a given speed.

#include "emulator/links/hand_link_timing.hpp"

#include "marsokhod/emulator/links/link_framing.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace marsokhod::emulator {
namespace {

using Kind = LinkStep::Kind;

using link_testing::hand_timing;

struct Transfer {
  Tick last_ack = 0;                   // when the last sender saw its last acknowledge
  Tick last_delivery = 0;              // when the last byte reached a receiver
  std::uint64_t delivered[2] = {0, 0}; // bytes delivered, by sending end
};

/// Runs the machine until nothing can happen; each end sends `bytes[end]` to a peer that
/// waits for all of them from time `start[end]`.
Transfer run(LinkFraming& link, std::uint64_t bytes0, std::uint64_t bytes1, Tick start1 = 0) {
  link.offer_output(0, 0, bytes0);
  link.offer_input(1, 0, bytes0);
  Transfer result;
  bool offered1 = false;
  for (;;) {
    if (!offered1 && link.next_time() >= start1) {
      link.offer_output(1, start1, bytes1);
      link.offer_input(0, start1, bytes1);
      offered1 = true;
    }
    const LinkStep step = link.step();
    if (step.kind == Kind::none)
      break;
    if (step.kind == Kind::ack_end)
      result.last_ack = step.time;
    if (step.kind == Kind::data_end && step.accepted) {
      ++result.delivered[step.end];
      result.last_delivery = step.time;
    }
  }
  return result;
}

double kilobytes_per_second(std::uint64_t bytes, Tick time) {
  return static_cast<double>(bytes) / to_seconds(time) / 1000.0;
}

TEST(LinkTiming, BitTimesScaleWithSpeed) {
  LinkTimingSpec spec;
  spec.data_packet_bits = 11;
  spec.ack_packet_bits = 2;
  spec.ack_delay_bits = 5.5;
  spec.ack_turnaround_bits = 2;
  spec.ack_turnaround_fixed = 100'000;
  const LinkTiming ten = LinkTiming::from(spec, 10);
  EXPECT_EQ(ten.bit, 100'000); // 1 / 10 Mbit/s = 100 ns
  EXPECT_EQ(ten.data_packet, 1'100'000);
  EXPECT_EQ(ten.ack_delay, 550'000);
  EXPECT_EQ(ten.ack_turnaround, 300'000);
  const LinkTiming twenty = LinkTiming::from(spec, 20);
  EXPECT_EQ(twenty.bit, 50'000);
  EXPECT_EQ(twenty.ack_turnaround, 200'000); // 2 bits of 50 ns + the fixed 100 ns
  EXPECT_EQ(LinkTiming::from(spec, 5).bit, 200'000);
}

TEST(LinkFraming, OneWayBytesFollowBackToBackWhenTheAckLoopIsShorterThanAPacket) {
  LinkFraming link(hand_timing());
  const Transfer t = run(link, 100, 0);
  // Ack loop: 550 + 200 + 300 = 1050 ns < 1100 ns packet, so packets are back to back:
  // byte k starts at k * 1.1 us; the last ack ends 550 + 200 ns after the last start.
  EXPECT_EQ(t.delivered[0], 100U);
  EXPECT_EQ(t.last_delivery, 100 * 1'100'000);
  EXPECT_EQ(t.last_ack, 99 * 1'100'000 + 750'000);
}

TEST(LinkFraming, OneWayPeriodIsTheAckLoopWhenThatIsLonger) {
  LinkTiming timing = hand_timing();
  timing.ack_turnaround = 1'000'000; // loop 550 + 200 + 1000 = 1750 ns
  LinkFraming link(timing);
  const Transfer t = run(link, 10, 0);
  EXPECT_EQ(t.last_delivery, 9 * 1'750'000 + 1'100'000);
}

TEST(LinkFraming, BothWaysAcksWaitForTheDataOnTheirWire) {
  LinkFraming link(hand_timing());
  const Transfer t = run(link, 50, 50);
  // Symmetric start: each wire carries data (1.1 us), then the ack it owes (0.2 us); each
  // sender restarts 0.3 us after its ack: one byte per 1.6 us per direction.
  EXPECT_EQ(t.delivered[0], 50U);
  EXPECT_EQ(t.delivered[1], 50U);
  EXPECT_EQ(t.last_delivery, 49 * 1'600'000 + 1'100'000);
}

TEST(LinkFraming, UnwantedByteWaitsUnacknowledgedUntilAnInput) {
  LinkFraming link(hand_timing());
  link.offer_output(0, 0, 2);
  LinkStep step;
  do
    step = link.step();
  while (step.kind != Kind::none);
  // The first byte arrived into the one-byte buffer; without an ack the second never starts.
  EXPECT_TRUE(link.byte_waiting(1));
  EXPECT_EQ(link.output_left(0), 2U);
  EXPECT_EQ(link.now(), 1'100'000);

  EXPECT_TRUE(link.offer_input(1, 5'000'000, 2)); // the waiting byte is taken at once
  EXPECT_FALSE(link.byte_waiting(1));
  step = link.step();
  EXPECT_EQ(step.kind, Kind::ack_start);
  EXPECT_EQ(step.time, 5'000'000);
  step = link.step();
  EXPECT_EQ(step.kind, Kind::ack_end);
  EXPECT_EQ(step.time, 5'200'000);
  step = link.step();
  EXPECT_EQ(step.kind, Kind::data_start);
  EXPECT_EQ(step.time, 5'500'000); // 300 ns turnaround after the ack
}

TEST(LinkFraming, BrokenCableStopsTrafficAndTheSenderWaits) {
  LinkFraming link(hand_timing());
  link.set_broken(true);
  const Transfer t = run(link, 5, 0);
  EXPECT_EQ(t.delivered[0], 0U);
  EXPECT_EQ(link.output_left(0), 5U); // the first byte is sent, never acknowledged
  EXPECT_EQ(link.next_time(), kNever);
}

TEST(LinkFraming, PoweredOffPeerStopsTrafficMidMessage) {
  LinkFraming link(hand_timing());
  link.offer_output(0, 0, 10);
  link.offer_input(1, 0, 10);
  int delivered = 0;
  while (delivered < 3) {
    const LinkStep step = link.step();
    delivered += step.kind == Kind::data_end && step.accepted ? 1 : 0;
  }
  link.reset_end(1, link.now(), false);
  LinkStep step;
  do {
    step = link.step();
    EXPECT_FALSE(step.kind == Kind::data_end && step.accepted);
  } while (step.kind != Kind::none);
  EXPECT_GT(link.output_left(0), 0U);
  EXPECT_EQ(link.next_time(), kNever);
}

// Data-book figures (T805.md, "Links": [M] datasheet table; [V] 2.4 MB/s both ways at 20 Mbit/s)
// from the shipped processor file's timing; each within 5 %.
class DataBookThroughput : public testing::Test {
protected:
  static LinkTiming shipped(int mbps) {
    const auto platform =
        load_platform(std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "pc-card.toml");
    return LinkTiming::from(platform.link_timing, mbps);
  }
  static double one_way(int mbps) {
    LinkFraming link(shipped(mbps));
    const std::uint64_t bytes = 20'000;
    return kilobytes_per_second(bytes, run(link, bytes, 0).last_delivery);
  }
  static double both_ways(int mbps, Tick offset) {
    LinkFraming link(shipped(mbps));
    const std::uint64_t bytes = 20'000;
    return kilobytes_per_second(2 * bytes, run(link, bytes, bytes, offset).last_delivery);
  }
};

TEST_F(DataBookThroughput, TenMegabitOneWayIsAbout910KBs) {
  EXPECT_NEAR(one_way(10), 910.0, 0.05 * 910.0);
}

TEST_F(DataBookThroughput, TenMegabitBothWaysIsAbout1250KBs) {
  EXPECT_NEAR(both_ways(10, 0), 1250.0, 0.05 * 1250.0);
}

TEST_F(DataBookThroughput, BothWaysHoldsWhenTheDirectionsStartOutOfPhase) {
  for (const Tick offset : {Tick{130'000}, Tick{370'000}, Tick{800'000}, Tick{1'450'000}})
    EXPECT_NEAR(both_ways(10, offset), 1250.0, 0.05 * 1250.0) << offset;
}

TEST_F(DataBookThroughput, TwentyMegabitOneWayIsAbout1740KBs) {
  EXPECT_NEAR(one_way(20), 1740.0, 0.05 * 1740.0);
}

TEST_F(DataBookThroughput, TwentyMegabitBothWaysIsAbout2350To2400KBs) {
  EXPECT_NEAR(both_ways(20, 0), 2375.0, 0.05 * 2350.0);
}

TEST_F(DataBookThroughput, FiveMegabitOneWayIsLimitedByTheWire) {
  // No data-book row for 5 Mbit/s. The handshake loop (5.5 + 2 + 2 bits of 200 ns + 100 ns =
  // 2.0 us) is shorter than a packet, so one byte per 11 bits of 200 ns: 454.5 KB/s.
  EXPECT_NEAR(one_way(5), 1.0 / (11 * 200e-9) / 1000.0, 0.01);
}

} // namespace
} // namespace marsokhod::emulator
