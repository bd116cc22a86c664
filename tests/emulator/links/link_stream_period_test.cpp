// A one-way stream repeats one byte period: the period found, and jumping whole periods
// landing exactly where stepping packet by packet lands.

#include "emulator/links/hand_link_timing.hpp"

#include "marsokhod/emulator/links/link_framing.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <vector>

namespace marsokhod::emulator {
namespace {

using Kind = LinkStep::Kind;

// The hand timing: packets back to back, 1.1 us each (the ack loop, 1050 ns, is shorter).
LinkTiming back_to_back() {
  return link_testing::hand_timing();
}

// The same with a 1000 ns turnaround: the ack loop, 550 + 200 + 1000 ns, sets the period.
LinkTiming ack_bound() {
  LinkTiming t = back_to_back();
  t.ack_turnaround = 1'000'000;
  return t;
}

LinkTiming shipped() {
  const auto platform =
      load_platform(std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "pc-card.toml");
  return LinkTiming::from(platform.link_timing, 10);
}

struct StreamRun {
  std::vector<Tick> periods;   // what stream_period() gave, in order
  std::uint64_t delivered = 0; // bytes delivered (stepped or jumped)
  std::uint64_t jumped = 0;    // of which jumped
  Tick last_delivery = 0;
  Tick last_ack = 0;
};

// Streams `bytes` from end 0 to end 1; with `jump`, every period found is jumped as far as
// the framing allows.
StreamRun stream(const LinkTiming& timing, std::uint64_t bytes, bool jump) {
  LinkFraming link(timing);
  link.offer_output(0, 0, bytes);
  link.offer_input(1, 0, bytes);
  StreamRun run;
  for (;;) {
    const LinkStep step = link.step();
    if (step.kind == Kind::none)
      break;
    if (step.kind == Kind::ack_end)
      run.last_ack = step.time;
    if (step.kind == Kind::data_end && step.accepted) {
      ++run.delivered;
      run.last_delivery = step.time;
    }
    if (step.kind != Kind::data_start)
      continue;
    const std::optional<Tick> period = link.stream_period(0);
    if (!period)
      continue;
    run.periods.push_back(*period);
    const std::uint64_t skip = link.skippable_bytes(0);
    if (!jump || skip == 0)
      continue;
    link.skip_stream(0, skip, *period);
    run.delivered += skip;
    run.jumped += skip;
  }
  return run;
}

TEST(LinkStreamPeriod, BackToBackPacketsRepeatEveryPacketTime) {
  const StreamRun run = stream(back_to_back(), 50, false);
  ASSERT_FALSE(run.periods.empty());
  for (const Tick period : run.periods)
    EXPECT_EQ(period, 1'100'000);
  // Every data start after the second compares with the one before it.
  EXPECT_GE(run.periods.size(), 47U);
}

TEST(LinkStreamPeriod, AnAckBoundStreamRepeatsEveryAckLoop) {
  const StreamRun run = stream(ack_bound(), 50, false);
  ASSERT_FALSE(run.periods.empty());
  for (const Tick period : run.periods)
    EXPECT_EQ(period, 1'750'000); // 550 + 200 + 1000 ns
}

TEST(LinkStreamPeriod, JumpingLandsWhereSteppingLands) {
  for (const LinkTiming& timing : {back_to_back(), ack_bound(), shipped()}) {
    const StreamRun stepped = stream(timing, 1000, false);
    const StreamRun jumped = stream(timing, 1000, true);
    EXPECT_EQ(stepped.jumped, 0U);
    EXPECT_GT(jumped.jumped, 900U) << "most of the stream is jumped";
    EXPECT_EQ(jumped.delivered, 1000U);
    EXPECT_EQ(stepped.delivered, 1000U);
    EXPECT_EQ(jumped.last_delivery, stepped.last_delivery);
    EXPECT_EQ(jumped.last_ack, stepped.last_ack);
  }
  // By hand: back to back, the last byte arrives at 1000 x 1.1 us.
  EXPECT_EQ(stream(back_to_back(), 1000, true).last_delivery, 1000 * 1'100'000);
}

TEST(LinkStreamPeriod, NoJumpCoversTheLastByte) {
  LinkFraming link(back_to_back());
  link.offer_output(0, 0, 10);
  link.offer_input(1, 0, 4); // the receiver takes fewer than are sent
  EXPECT_EQ(link.skippable_bytes(0), 3U);
  link.withdraw_input(1);
  EXPECT_EQ(link.skippable_bytes(0), 0U);
}

TEST(LinkStreamPeriod, AnOfferBetweenTwoDataStartsHidesThePeriodUntilTheStreamRepeatsAgain) {
  LinkFraming link(back_to_back());
  link.offer_output(0, 0, 40);
  link.offer_input(1, 0, 40);
  std::vector<bool> found; // per data start
  bool offered = false;
  for (LinkStep step = link.step(); step.kind != Kind::none; step = link.step()) {
    if (step.kind != Kind::data_start)
      continue;
    found.push_back(link.stream_period(0).has_value());
    if (found.size() == 20 && !offered) {
      link.offer_input(1, link.now(), 1); // a second input of one byte, and its byte
      link.offer_output(0, link.now(), 1);
      offered = true;
    }
  }
  ASSERT_EQ(found.size(), 41U);
  EXPECT_TRUE(found[19]);
  EXPECT_FALSE(found[20]) << "compared across the offers";
  EXPECT_TRUE(found[21]);
}

TEST(LinkStreamPeriod, BothWaysAtOnceIsNoOneWayStream) {
  LinkFraming link(shipped());
  for (int end = 0; end < 2; ++end) {
    link.offer_output(end, 0, 200);
    link.offer_input(1 - end, 0, 200);
  }
  int found = 0;
  for (LinkStep step = link.step(); step.kind != Kind::none; step = link.step())
    if (step.kind == Kind::data_start && link.stream_period(step.end))
      ++found;
  EXPECT_EQ(found, 0);
}

} // namespace
} // namespace marsokhod::emulator
