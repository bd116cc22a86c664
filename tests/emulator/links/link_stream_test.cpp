// The link throughput experiment: streams arrive intact at the wire rate.

#include "support/test_files.hpp"

#include "marsokhod/emulator/links/link_stream.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace marsokhod::emulator {
namespace {

using test_support::kPlatforms;

TEST(LinkStream, OneWayStreamArrivesIntactAtTheWireRate) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  LinkStreamOptions options;
  options.bytes = 5000;
  options.message_bytes = 1000;
  const LinkStreamResult result = run_link_stream(onboard, options);
  EXPECT_TRUE(result.intact);
  EXPECT_EQ(result.from, "module0.link0");
  EXPECT_EQ(result.to, "module1.link0");
  EXPECT_EQ(result.bytes_moved, 5000U);
  // 11 bits of 100 ns per byte (T805.md framing at 10 Mbit/s), plus per message the 19-cycle
  // out/in instructions and handshakes: within 0.5 % of 5000 x 1.1 us.
  EXPECT_NEAR(to_microseconds(result.elapsed), 5000 * 1.1, 0.005 * 5000 * 1.1);
}

TEST(LinkStream, BothWaysMovesTwiceTheBytes) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  LinkStreamOptions options;
  options.bytes = 3000;
  options.both_ways = true;
  options.mbps = 20;
  const LinkStreamResult result = run_link_stream(onboard, options);
  EXPECT_TRUE(result.intact);
  EXPECT_EQ(result.mbps, 20);
  EXPECT_EQ(result.bytes_moved, 6000U);
}

TEST(LinkStream, SameOptionsGiveTheSameEmulatedTime) {
  const PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  LinkStreamOptions options;
  options.bytes = 2000;
  options.both_ways = true;
  EXPECT_EQ(run_link_stream(onboard, options).elapsed, run_link_stream(onboard, options).elapsed);
}

TEST(LinkStream, PlatformWithoutTwoPoweredWiredNodesIsRefused) {
  PlatformSpec card = load_platform(kPlatforms / "pc-card.toml");
  EXPECT_THROW(run_link_stream(card, LinkStreamOptions{}), std::invalid_argument);
  PlatformSpec onboard = load_platform(kPlatforms / "onboard.toml");
  for (NodeSpec& node : onboard.nodes)
    node.powered = node.name == "module0";
  EXPECT_THROW(run_link_stream(onboard, LinkStreamOptions{}), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::emulator
