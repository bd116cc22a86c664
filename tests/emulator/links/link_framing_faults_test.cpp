// The framing machine under wire faults and channel resets, step by step.
//
// Hand timing: a byte's data packet takes 1.1 us, its acknowledge starts 0.55 us after the
// start bit and ends 0.2 us later; the next byte may start 0.3 us after that.

#include "emulator/links/hand_link_timing.hpp"

#include "marsokhod/emulator/links/link_framing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <vector>

namespace marsokhod::emulator {
namespace {

using Kind = LinkStep::Kind;
using link_testing::hand_timing;

std::vector<LinkStep> steps_until_idle(LinkFraming& link) {
  std::vector<LinkStep> steps;
  for (LinkStep step = link.step(); step.kind != Kind::none; step = link.step())
    steps.push_back(step);
  return steps;
}

TEST(LinkFramingFaults, DataStartingOnADeadWireIsLostWhole) {
  LinkFraming link(hand_timing());
  link.set_wire_dead(0, true);
  link.offer_output(0, 0, 3);
  link.offer_input(1, 0, 3);
  const std::vector<LinkStep> steps = steps_until_idle(link);
  ASSERT_EQ(steps.size(), 2U);
  EXPECT_EQ(steps[0].kind, Kind::data_start);
  EXPECT_TRUE(steps[0].lost);
  EXPECT_EQ(steps[1].kind, Kind::data_end);
  EXPECT_EQ(steps[1].time, 1'100'000);
  EXPECT_FALSE(steps[1].accepted);
  EXPECT_FALSE(link.byte_waiting(1));
  EXPECT_EQ(link.output_left(0), 3U);
  EXPECT_EQ(link.input_left(1), 3U);
}

TEST(LinkFramingFaults, AcknowledgeOnADeadWireIsLostAndItsSenderWaits) {
  LinkFraming link(hand_timing());
  link.set_wire_dead(1, true);
  link.offer_output(0, 0, 3);
  link.offer_input(1, 0, 3);
  const std::vector<LinkStep> steps = steps_until_idle(link);
  ASSERT_EQ(steps.size(), 4U);
  EXPECT_EQ(steps[1].kind, Kind::ack_start);
  EXPECT_EQ(steps[1].time, 550'000);
  EXPECT_TRUE(steps[1].lost);
  EXPECT_EQ(steps[2].kind, Kind::ack_end);
  EXPECT_FALSE(steps[2].accepted);
  EXPECT_EQ(steps[3].kind, Kind::data_end);
  EXPECT_TRUE(steps[3].accepted); // the data wire is alive: byte 0 arrives
  EXPECT_EQ(link.output_left(0), 3U);
}

TEST(LinkFramingFaults, PacketAlreadyOnTheWireWhenItDiesStillArrives) {
  LinkFraming link(hand_timing());
  link.offer_output(0, 0, 2);
  link.offer_input(1, 0, 2);
  ASSERT_EQ(link.step().kind, Kind::data_start);
  link.set_wire_dead(0, true);
  const std::vector<LinkStep> steps = steps_until_idle(link);
  // Byte 0 arrives and is acknowledged; byte 1 starts at 1.1 us on the dead wire.
  ASSERT_EQ(steps.size(), 5U);
  EXPECT_EQ(steps[2].kind, Kind::data_end);
  EXPECT_TRUE(steps[2].accepted);
  EXPECT_EQ(steps[3].kind, Kind::data_start);
  EXPECT_EQ(steps[3].time, 1'100'000);
  EXPECT_TRUE(steps[3].lost);
  EXPECT_FALSE(steps[4].accepted);
  EXPECT_EQ(link.output_left(0), 1U);
}

TEST(LinkFramingFaults, LostAcknowledgeIsOnlyTheNextOne) {
  LinkFraming link(hand_timing());
  link.lose_acknowledge(1);
  link.offer_output(0, 0, 1);
  link.offer_input(1, 0, 2);
  const std::vector<LinkStep> first = steps_until_idle(link);
  ASSERT_EQ(first.size(), 4U);
  EXPECT_TRUE(first[1].lost);
  EXPECT_FALSE(first[2].accepted);
  EXPECT_EQ(link.output_left(0), 1U);

  link.reset_output(0, 5'000'000);
  EXPECT_EQ(link.output_left(0), 0U);
  link.offer_output(0, 5'000'000, 1);
  const std::vector<LinkStep> second = steps_until_idle(link);
  ASSERT_EQ(second.size(), 4U);
  EXPECT_EQ(second[0].time, 5'000'000);
  EXPECT_FALSE(second[1].lost);
  EXPECT_EQ(second[2].kind, Kind::ack_end);
  EXPECT_TRUE(second[2].accepted);
  EXPECT_EQ(link.output_left(0), 0U);
}

TEST(LinkFramingFaults, InputResetDropsAByteItTookOnTheWire) {
  LinkFraming link(hand_timing());
  link.offer_output(0, 0, 1);
  link.offer_input(1, 0, 1);
  ASSERT_EQ(link.step().kind, Kind::data_start); // taken at once: its receiver waits
  link.reset_input(1, 300'000);
  const std::vector<LinkStep> steps = steps_until_idle(link);
  ASSERT_EQ(steps.size(), 1U); // no acknowledge goes
  EXPECT_EQ(steps[0].kind, Kind::data_end);
  EXPECT_FALSE(steps[0].accepted);
  EXPECT_FALSE(link.byte_waiting(1));
  EXPECT_EQ(link.output_left(0), 1U);
}

TEST(LinkFramingFaults, BrokenCableIsBothWiresDead) {
  LinkFraming link(hand_timing());
  link.set_broken(true);
  EXPECT_TRUE(link.wire_dead(0));
  EXPECT_TRUE(link.wire_dead(1));
  link.set_wire_dead(0, false);
  EXPECT_FALSE(link.broken());
  link.set_broken(false);
  EXPECT_FALSE(link.wire_dead(1));
}

struct Streamed {
  std::uint64_t delivered = 0;
  std::uint64_t jumped = 0;
  Tick last_delivery = 0;
  Tick last_ack = 0;
  Tick idle_at = 0;
  std::uint64_t output_left = 0;
  std::uint64_t input_left = 0;
};

// 200 bytes from end 0; at 55.2 us (between two steps, as a kernel event would be) the
// receiver's next acknowledge is lost. With `jump`, every period found is jumped as far as the
// framing allows without passing 55.2 us, as Link::jump_stream() stops at the next event.
Streamed stream_losing_an_acknowledge(bool jump) {
  constexpr Tick kLoss = 55'200'000;
  LinkFraming link(hand_timing());
  link.offer_output(0, 0, 200);
  link.offer_input(1, 0, 200);
  Streamed run;
  bool lost = false;
  for (;;) {
    if (!lost && link.next_time() > kLoss) {
      link.lose_acknowledge(1);
      lost = true;
    }
    const LinkStep step = link.step();
    if (step.kind == Kind::none)
      break;
    if (step.kind == Kind::ack_end && step.accepted)
      run.last_ack = step.time;
    if (step.kind == Kind::data_end && step.accepted) {
      ++run.delivered;
      run.last_delivery = step.time;
    }
    if (step.kind != Kind::data_start)
      continue;
    const std::optional<Tick> period = link.stream_period(0);
    if (!jump || !period)
      continue;
    std::uint64_t skip = link.skippable_bytes(0);
    if (!lost)
      skip = std::min(skip, static_cast<std::uint64_t>((kLoss - 1 - link.now()) / *period));
    if (skip == 0)
      continue;
    link.skip_stream(0, skip, *period);
    run.delivered += skip;
    run.jumped += skip;
  }
  run.idle_at = link.now();
  run.output_left = link.output_left(0);
  run.input_left = link.input_left(1);
  return run;
}

TEST(LinkFramingFaults, NoJumpCarriesAStreamPastALostAcknowledge) {
  const Streamed stepped = stream_losing_an_acknowledge(false);
  const Streamed jumped = stream_losing_an_acknowledge(true);
  EXPECT_GT(jumped.jumped, 0U);
  // Byte 49's acknowledge ended at 54.65 us; byte 50 starts at 55.0 us, arrives at 56.1 us,
  // and its acknowledge (from 55.55 us) is the lost one: byte 51 never starts.
  EXPECT_EQ(stepped.delivered, 51U);
  EXPECT_EQ(stepped.last_delivery, 51 * 1'100'000);
  EXPECT_EQ(stepped.last_ack, 49 * 1'100'000 + 750'000);
  EXPECT_EQ(stepped.idle_at, 51 * 1'100'000);
  EXPECT_EQ(stepped.output_left, 150U); // bytes 0..49 acknowledged
  EXPECT_EQ(stepped.input_left, 149U);
  // Jumped acknowledges are not stepped, so only the stepped run reports them.
  EXPECT_EQ(jumped.delivered, stepped.delivered);
  EXPECT_EQ(jumped.last_delivery, stepped.last_delivery);
  EXPECT_EQ(jumped.idle_at, stepped.idle_at);
  EXPECT_EQ(jumped.output_left, stepped.output_left);
  EXPECT_EQ(jumped.input_left, stepped.input_left);
}

} // namespace
} // namespace marsokhod::emulator
