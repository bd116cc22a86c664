// Block channels of the navigation program: a block in memory costs the data-book in/out on
// each side; on a link the bytes arrive as they were sent and are counted.

#include "occam_port/link_rig.hpp"
#include "occam_port/occam_rig.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav_program/channels/block_channel.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace marsokhod::nav_program {
namespace {

TEST(BlockChannel, ABlockInMemoryCostsEachSideTheDataBookInOut) {
  occam_port::testing::OccamRig rig;
  BlockChannel channel("block");
  const std::vector<std::byte> sent = test_support::byte_pattern(400);
  std::vector<std::byte> received(400);
  rig.spawn(
      "sender", [&] { channel.send(sent); });
  rig.spawn("receiver", [&] { channel.receive(received); });
  rig.kernel.run();
  EXPECT_EQ(received, sent);
  // 400 bytes = 100 words: each side loads its operands (ldlp, ldl, ldc: 4 cycles) and runs
  // in or out, 2 x 100 + 19 cycles (data book); one CPU runs both sides one after the other.
  EXPECT_EQ(rig.kernel.now(), rig.cycles(2 * (4 + 2 * 100 + 19)));
  EXPECT_EQ(channel.bytes_carried(), 400U);
  EXPECT_EQ(channel.blocks_carried(), 1U);
}

TEST(BlockChannel, ReceivingIntoABufferOfAnotherLengthIsAProtocolError) {
  occam_port::testing::OccamRig rig;
  BlockChannel channel("block");
  const std::vector<std::byte> sent = test_support::byte_pattern(8);
  std::vector<std::byte> received(12);
  rig.spawn(
      "sender", [&] { channel.send(sent); });
  rig.spawn("receiver", [&] { channel.receive(received); });
  EXPECT_THROW(rig.kernel.run(), std::logic_error);
}

TEST(BlockChannel, OnALinkTheBytesArriveInOrderAndAreCounted) {
  occam_port::testing::TwoModules rig;
  BlockChannel channel("over the link");
  channel.place_on_link(*rig.m0.link(0), *rig.m1.link(0));
  ASSERT_TRUE(channel.external());
  const std::vector<std::byte> first = test_support::byte_pattern(300);
  const std::vector<std::byte> second = test_support::byte_pattern(5);
  std::vector<std::byte> got_first(300);
  std::vector<std::byte> got_second(5);
  rig.m0.spawn("sender", [&] {
    channel.send(first);
    channel.send(second);
  });
  rig.m1.spawn("receiver", [&] {
    channel.receive(got_first);
    channel.receive(got_second);
  });
  rig.kernel.run();
  EXPECT_EQ(got_first, first);
  EXPECT_EQ(got_second, second);
  EXPECT_EQ(channel.bytes_carried(), 305U);
  EXPECT_EQ(channel.blocks_carried(), 2U);
  // 305 bytes of 11 bits at 10 Mbit/s, each acknowledged before the next: at least 1.1 us each.
  EXPECT_GE(emulator::to_microseconds(rig.kernel.now()), 305 * 1.1);
}

} // namespace
} // namespace marsokhod::nav_program
