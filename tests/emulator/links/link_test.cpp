// T805 links: transfers, handshake timing, dead ends and broken wires.

#include "emulator/links/hand_link_timing.hpp"
#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/node/node.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <vector>

namespace marsokhod::emulator {
namespace {

using test_support::kPlatforms;

using link_testing::hand_timing;

struct TwoNodes : testing::Test {
  Kernel kernel;
  Cpu& a = kernel.add_cpu("a");
  Cpu& b = kernel.add_cpu("b");
  Link link{kernel, "a.link0", "b.link0", hand_timing()};
};

TEST_F(TwoNodes, MessageArrivesIntactAtTheWireRate) {
  const std::vector<std::byte> sent = test_support::byte_pattern(1000);
  std::vector<std::byte> received(1000);
  Tick sender_done = 0;
  Tick receiver_done = 0;
  kernel.spawn(a, "sender", [&] {
    link.port(0).output(sent);
    sender_done = kernel.now();
  });
  kernel.spawn(b, "receiver", [&] {
    link.port(1).input(received);
    receiver_done = kernel.now();
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, sent);
  // Back-to-back packets: the last byte ends at 1000 x 1.1 us; its ack ends 0.75 us after
  // its start bit.
  EXPECT_EQ(receiver_done, 1000 * 1'100'000);
  EXPECT_EQ(sender_done, 999 * 1'100'000 + 750'000);
}

TEST_F(TwoNodes, LateReceiverHoldsTheSenderAfterOneByte) {
  const std::vector<std::byte> sent = test_support::byte_pattern(10);
  std::vector<std::byte> received(10);
  Tick receiver_done = 0;
  kernel.spawn(a, "sender", [&] { link.port(0).output(sent); });
  kernel.spawn(b, "receiver", [&] {
    kernel.consume(microseconds(50));
    link.port(1).input(received);
    receiver_done = kernel.now();
  });
  kernel.run();
  EXPECT_EQ(received, sent);
  // Byte 0 waits in the buffer; the input at 50 us acks it (0.2 us), the sender restarts
  // 0.3 us later and the other 9 bytes follow back to back.
  EXPECT_EQ(receiver_done, microseconds(50) + 500'000 + 9 * 1'100'000);
}

TEST_F(TwoNodes, LinkTransferOverlapsComputationOnTheSameNode) {
  const std::vector<std::byte> sent = test_support::byte_pattern(100);
  std::vector<std::byte> received(100);
  Tick compute_done = 0;
  kernel.spawn(a, "sender", [&] { link.port(0).output(sent); });
  kernel.spawn(
      a, "worker",
      [&] {
        kernel.consume(microseconds(80));
        compute_done = kernel.now();
      });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  kernel.run();
  // The 110 us transfer runs on the link engine; the worker gets the CPU for its 80 us at once.
  EXPECT_EQ(compute_done, microseconds(80));
  EXPECT_EQ(received, sent);
}

TEST_F(TwoNodes, ArrivalListenerFiresWhenAByteWaits) {
  Tick heard = -1;
  link.port(1).set_arrival_listener([&] { heard = kernel.now(); });
  const std::vector<std::byte> sent = test_support::byte_pattern(3);
  kernel.spawn(a, "sender", [&] { link.port(0).output(sent); });
  kernel.run();
  EXPECT_EQ(heard, 1'100'000); // end of the first data packet
  EXPECT_TRUE(link.port(1).byte_waiting());
}

TEST_F(TwoNodes, PoweredOffPeerStopsTrafficAndItsPeersTimedWaitExpires) {
  const std::vector<std::byte> sent = test_support::byte_pattern(1000);
  std::vector<std::byte> received(1000);
  bool sender_finished = false;
  bool timed_out = false;
  kernel.spawn(
      a, "sender",
      [&] {
        link.port(0).output(sent);
        sender_finished = true;
      });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  // Node a also waits for a reply from b with a 200 us timeout, as an ALT with AFTER would.
  Link reply{kernel, "a.link1", "b.link1", hand_timing()};
  kernel.spawn(a, "listener", [&] {
    const Tick deadline = microseconds(200);
    while (!reply.port(0).byte_waiting() && kernel.now() < deadline) {
      Process& self = *kernel.current();
      reply.port(0).set_arrival_listener([&] { kernel.wake(self); });
      timed_out = kernel.block_until(deadline, WaitInfo{WaitKind::alt, &reply.port(0)});
    }
    reply.port(0).set_arrival_listener({});
  });
  kernel.schedule_at(microseconds(100), event_priority::power, [&] {
    kernel.kill_all(b);
    link.set_powered(1, false);
    reply.set_powered(1, false);
  });
  const RunResult result = kernel.run();
  EXPECT_TRUE(timed_out);
  EXPECT_FALSE(sender_finished);
  EXPECT_EQ(result.reason, StopReason::deadlock);
  ASSERT_TRUE(result.deadlock.has_value());
  ASSERT_EQ(result.deadlock->processes.size(), 1U);
  EXPECT_EQ(result.deadlock->processes[0].process, "sender");
  EXPECT_EQ(result.deadlock->processes[0].kind, WaitKind::link_output);
}

TEST_F(TwoNodes, BrokenCableCarriesNothing) {
  link.set_broken(true);
  const std::vector<std::byte> sent = test_support::byte_pattern(4);
  std::vector<std::byte> received(4, std::byte{0});
  kernel.spawn(
      a, "sender", [&] { link.port(0).output(sent); });
  kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  const RunResult result = kernel.run();
  EXPECT_EQ(result.reason, StopReason::deadlock);
  EXPECT_EQ(received, std::vector<std::byte>(4, std::byte{0}));
}

TEST_F(TwoNodes, LinkWorksAgainAfterThePeerIsPoweredBackOn) {
  const std::vector<std::byte> sent = test_support::byte_pattern(20);
  std::vector<std::byte> received(20);
  kernel.spawn(
      b, "doomed",
      [&] {
        std::vector<std::byte> sink(20);
        link.port(1).input(sink);
      });
  kernel.spawn(a, "first", [&] { link.port(0).output(sent); });
  kernel.schedule_at(
      microseconds(5), event_priority::power,
      [&] {
        kernel.kill_all(b);
        link.set_powered(1, false);
        kernel.kill_all(a);
        link.set_powered(0, false);
      });
  kernel.schedule_at(microseconds(10), event_priority::power, [&] {
    link.set_powered(0, true);
    link.set_powered(1, true);
    kernel.spawn(a, "second", [&] { link.port(0).output(sent); });
    kernel.spawn(b, "receiver", [&] { link.port(1).input(received); });
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(received, sent);
}

TEST_F(TwoNodes, BothDirectionsAtOnceDeliverEverything) {
  const std::vector<std::byte> ab = test_support::byte_pattern(300);
  std::vector<std::byte> ba(300);
  std::iota(reinterpret_cast<unsigned char*>(ba.data()),
            reinterpret_cast<unsigned char*>(ba.data()) + ba.size(), static_cast<unsigned char>(1));
  std::vector<std::byte> at_b(300);
  std::vector<std::byte> at_a(300);
  kernel.spawn(
      a, "a_out", [&] { link.port(0).output(ab); });
  kernel.spawn(
      a, "a_in", [&] { link.port(0).input(at_a); });
  kernel.spawn(
      b, "b_out", [&] { link.port(1).output(ba); });
  kernel.spawn(b, "b_in", [&] { link.port(1).input(at_b); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(at_b, ab);
  EXPECT_EQ(at_a, ba);
  // 1.6 us per byte and direction (1.1 data + 0.2 ack + 0.3 turnaround), see link_framing_test.
  EXPECT_EQ(kernel.now(), 299 * 1'600'000 + 1'100'000 + 200'000);
}

TEST(LinkNetwork, OnboardModulesTalkOnlyWhenPowered) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  Kernel kernel;
  Cpu& m0 = kernel.add_cpu("module0");
  Cpu& m1 = kernel.add_cpu("module1");
  LinkNetwork network(kernel, onboard);
  ASSERT_NE(network.port("module0", 0), nullptr);
  EXPECT_EQ(network.port("module0", 0)->name(), "module0.link0");
  EXPECT_EQ(&network.port("module0", 0)->link(), &network.port("module1", 0)->link());
  const std::vector<std::byte> sent = test_support::byte_pattern(64);
  std::vector<std::byte> received(64);
  bool to_spare_done = false;
  kernel.spawn(
      m0, "to_m1", [&] { network.require_port("module0", 0).output(sent); });
  kernel.spawn(m1, "from_m0", [&] { network.require_port("module1", 0).input(received); });
  // module2 is a cold spare (onboard.toml): nothing sent to it is acknowledged.
  kernel.spawn(m0, "to_spare", [&] {
    network.require_port("module0", 1).output(sent);
    to_spare_done = true;
  });
  kernel.run();
  EXPECT_EQ(received, sent);
  EXPECT_FALSE(to_spare_done);
}

TEST(LinkNetwork, SpeedOverrideMustBeAT805Speed) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  Kernel kernel;
  EXPECT_THROW(LinkNetwork(kernel, onboard, 15), std::invalid_argument);
  LinkNetwork fast(kernel, onboard, 20);
  EXPECT_EQ(fast.links().front()->framing().timing().bit, 50'000);
}

TEST(LinkNetwork, NodePowerSwitchReachesItsLinks) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  Kernel kernel;
  LinkNetwork network(kernel, onboard);
  Node m0(kernel, *onboard.find_node("module0"));
  Node m1(kernel, *onboard.find_node("module1"));
  network.attach(m0);
  network.attach(m1);
  ASSERT_EQ(m0.link(0), network.port("module0", 0));
  const std::vector<std::byte> sent = test_support::byte_pattern(1000);
  std::vector<std::byte> received(1000);
  bool delivered = false;
  m0.spawn(
      "sender",
      [&] {
        m0.link(0)->output(sent);
        delivered = true;
      });
  m1.spawn(
      "receiver", [&] { m1.link(0)->input(received); });
  kernel.schedule_at(microseconds(100), event_priority::power, [&] { m1.power_off(); });
  kernel.run();
  EXPECT_FALSE(delivered);
  EXPECT_FALSE(network.port("module0", 0)->link().framing().alive(1));
}

} // namespace
} // namespace marsokhod::emulator
