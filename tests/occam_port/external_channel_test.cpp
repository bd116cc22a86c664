// occam channels between two onboard modules, carried by the link engines.

#include "occam_port/link_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::StopReason;
using emulator::Tick;
using testing::TwoModules;

TEST(ExternalChannel, MessageCrossesTheLinkIntact) {
  TwoModules rig;
  Chan<std::array<int, 8>> c("m0->m1");
  rig.wire(c, rig.m0, rig.m1);
  const std::array<int, 8> sent = {1, -2, 3, -4, 5, -6, 7, -8};
  std::array<int, 8> received{};
  Tick received_at = -1;
  rig.m0.spawn("sender", [&] { c << sent; });
  rig.m1.spawn("receiver", [&] {
    c >> received;
    received_at = rig.kernel.now();
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, sent);
  // 32 bytes one way at 10 Mbit/s take at least 32 data packets of 11 bits (1.1 us each).
  EXPECT_GE(received_at, 32 * emulator::nanoseconds(1100));
}

TEST(ExternalChannel, LinkDmaMovesTheBytesSoEachCpuPaysOnlyTheInstructionBase) {
  TwoModules rig;
  Chan<std::array<std::byte, 4096>> c("m0->m1");
  rig.wire(c, rig.m0, rig.m1);
  std::array<std::byte, 4096> sent{};
  sent.fill(std::byte{0x5a});
  std::array<std::byte, 4096> received{};
  rig.m0.spawn(
      "sender", [&] { c << sent; });
  rig.m1.spawn("receiver", [&] { c >> received; });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, sent);
  // Data book: operand loads ldlp 1 + ldl 2 + ldc 1, then out/in 19 without the 2 cycles per
  // word an internal copy would add (1024 words, 2048 cycles).
  const emulator::Tick base_only = (1 + 2 + 1 + 19) * rig.m0.cpu_spec().cycle;
  EXPECT_EQ(rig.m0.cpu().busy_time(), base_only);
  EXPECT_EQ(rig.m1.cpu().busy_time(), base_only);
  // The bytes still take the link's time: 4096 packets of 11 bits at 10 Mbit/s at least.
  EXPECT_GE(rig.kernel.now(), 4096 * emulator::nanoseconds(1100));
}

TEST(ExternalChannel, AltOnALinkChannelIsWokenByTheFirstByte) {
  TwoModules rig;
  Chan<int> c("m0->m1");
  rig.wire(c, rig.m0, rig.m1);
  std::size_t chosen = 99;
  int value = 0;
  rig.m0.spawn(
      "sender",
      [&] {
        compute(emulator::Instruction::mul, 100);
        c << 1234;
      });
  rig.m1.spawn("alting", [&] {
    Timer tim;
    chosen = pri_alt({input(c), after(tim, tim.read() + 1000)});
    if (chosen == 0) {
      c >> value;
    }
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(chosen, 0U);
  EXPECT_EQ(value, 1234);
}

TEST(ExternalChannel, PoweringTheServerOffMidExchangeLetsTheClientAltTimeOut) {
  TwoModules rig;
  Chan<int> request("request"), reply("reply");
  rig.wire(request, rig.m1, rig.m0);
  reply.place_on_link(*rig.m0.link(0), *rig.m1.link(0));
  std::vector<int> replies;
  bool timed_out = false;
  Tick timed_out_at = -1;
  std::int32_t deadline = 0;
  bool server_unwound = false;
  struct Flag {
    bool* set;
    ~Flag() { *set = true; }
  };
  rig.m0.spawn("server", [&] {
    Flag flag{&server_unwound};
    for (;;) {
      int n = 0;
      request >> n;
      compute(emulator::Instruction::mul, 100); // 3800 cycles, about 127 us
      reply << 2 * n;
    }
  });
  rig.m1.spawn("client", [&] {
    Timer tim;
    for (int i = 0; !timed_out; ++i) {
      request << i;
      deadline = tim.read() + 10; // low priority: 10 ticks of 64 us
      if (pri_alt({input(reply), after(tim, deadline)}) == 0) {
        int answer = 0;
        reply >> answer;
        replies.push_back(answer);
      } else {
        timed_out = true;
        timed_out_at = rig.kernel.now();
      }
    }
  });
  // Mid-exchange: the server is computing its third answer.
  const Tick off = emulator::microseconds(350);
  rig.kernel.schedule_at(off, emulator::event_priority::power, [&] { rig.m0.power_off(); });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_TRUE(server_unwound);
  EXPECT_TRUE(timed_out);
  ASSERT_GE(replies.size(), 1U);
  for (std::size_t i = 0; i < replies.size(); ++i)
    EXPECT_EQ(replies[i], 2 * static_cast<int>(i));
  // The ALT gives up when the low-priority clock passes the deadline (64 us ticks), and not
  // before the power went off.
  EXPECT_GT(timed_out_at, off);
  EXPECT_EQ(Timer::clock_at(timed_out_at, emulator::microseconds(64)), deadline + 1);
}

} // namespace
} // namespace marsokhod::occam_port
