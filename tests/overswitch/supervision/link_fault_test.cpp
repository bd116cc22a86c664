// Link faults between the powered modules: a stalled output is given up one link timeout after
// it began and reported; the first trouble on a wire restarts the cycle on the same pair, the
// second fails the far module over; a flipped bit is caught by the checksums alone.

#include "overswitch/onboard_cycle.hpp"

#include <gtest/gtest.h>

namespace marsokhod::overswitch {
namespace {

using namespace test;

/// platforms/onboard.toml, [overswitch] link_timeout_us.
constexpr Tick kLinkTimeout = 100 * kMs;

class LinkFaultTest : public OnboardCycle {
protected:
  static Fault on_link(Fault::Kind kind, const std::string& module, int link, Tick at,
                       LinkDirection direction) {
    Fault f = fault(kind, module, at);
    f.link = link;
    f.direction = direction;
    return f;
  }

  /// When module0 first outputs on link 0 (the first matched band): a link dead from the start
  /// stalls that output, which is given up one timeout later.
  Tick first_band_output() {
    FailoverSupervisor* supervisor = nullptr;
    emulate({on_link(Fault::Kind::link_down, "module0", 0, 0, LinkDirection::both)}, supervisor);
    EXPECT_FALSE(supervisor->troubles().empty());
    return supervisor->troubles().empty() ? 0 : supervisor->troubles()[0].at - kLinkTimeout;
  }
};

TEST_F(LinkFaultTest, DeadLinkIsRestartedOnceThenItsFarModuleFailsOver) {
  const Tick first_band = first_band_output();
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate(
      {on_link(Fault::Kind::link_down, "module0", 0, 2000 * kMs, LinkDirection::both)}, supervisor);
  const auto& troubles = supervisor->troubles();
  ASSERT_EQ(troubles.size(), 2U);
  EXPECT_EQ(troubles[0].module, "module0");
  EXPECT_EQ(troubles[0].peer, "module1");
  EXPECT_EQ(troubles[0].trouble, nav_program::LinkTrouble::timeout);
  // The stalled output began at or after the fault (or was under way, at most one band long:
  // 0.6 ms), and was given up one timeout later.
  EXPECT_GE(troubles[0].at, 2000 * kMs + kLinkTimeout - 600 * kUs);
  // The restarted cycle reaches its first band when the cycle from rest does, and stalls there.
  EXPECT_NEAR(static_cast<double>(troubles[1].at - troubles[0].at),
              static_cast<double>(first_band + kLinkTimeout), 50.0 * kUs);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 1U);
  EXPECT_EQ(failovers[0].failed, "module1");
  EXPECT_EQ(failovers[0].spare, "module2");
  EXPECT_EQ(failovers[0].booted_from, "module0");
  EXPECT_EQ(failovers[0].detected, troubles[1].at);
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 2);
  EXPECT_TRUE(same_path(run, golden()));
}

// A partner that has lost its power cannot take module0's next output: the sender's timeout,
// 100 ms after that output began, comes before the watchdog's expiry (200 ms after module1's
// last kick, the one at the cycle's start) and the overswitch fails module1 over at once, with
// no restart on the same pair.
TEST_F(LinkFaultTest, PartnerLostBeforeAnOutputIsFailedOverByTheSendersTimeout) {
  const Tick first_band = first_band_output();
  const Tick strike = 10 * kMs;
  ASSERT_GT(first_band, strike);
  ASSERT_LT(first_band + kLinkTimeout, 200 * kMs);
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run =
      emulate({fault(Fault::Kind::power_loss, "module1", strike)}, supervisor);
  const auto& troubles = supervisor->troubles();
  ASSERT_EQ(troubles.size(), 1U);
  EXPECT_EQ(troubles[0].module, "module0");
  EXPECT_EQ(troubles[0].peer, "module1");
  EXPECT_NEAR(static_cast<double>(troubles[0].at), static_cast<double>(first_band + kLinkTimeout),
              50.0 * kUs);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 1U);
  EXPECT_EQ(failovers[0].failed, "module1");
  EXPECT_EQ(failovers[0].spare, "module2");
  EXPECT_EQ(failovers[0].detected, troubles[0].at);
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 1); // the failover's, none on the same pair
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(LinkFaultTest, WireDownForAMomentIsRecoveredOnTheSamePair) {
  const Tick first_band = first_band_output();
  Fault down = on_link(Fault::Kind::link_down, "module0", 0, 0, LinkDirection::both);
  down.duration = first_band + 20 * kMs; // mended long before the timeout
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({down}, supervisor);
  ASSERT_EQ(supervisor->troubles().size(), 1U);
  EXPECT_EQ(supervisor->troubles()[0].at, first_band + kLinkTimeout);
  EXPECT_TRUE(supervisor->overswitch().failovers().empty());
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 1);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(LinkFaultTest, LostAcknowledgeStallsTheSenderUntilItsTimeout) {
  const Tick first_band = first_band_output();
  FailoverSupervisor* supervisor = nullptr;
  // The receiver's next acknowledge, on the wire module0 listens to.
  const CycleEmulation run =
      emulate({on_link(Fault::Kind::ack_lost, "module0", 0, 0, LinkDirection::in)}, supervisor);
  ASSERT_EQ(supervisor->troubles().size(), 1U);
  EXPECT_EQ(supervisor->troubles()[0].at, first_band + kLinkTimeout);
  EXPECT_TRUE(supervisor->overswitch().failovers().empty());
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(LinkFaultTest, FlippedBitIsSilentWithoutChecksumsAndReportedByTheReceiverWithThem) {
  Fault flip = on_link(Fault::Kind::link_bit, "module0", 0, 0, LinkDirection::out);
  flip.byte = 10;
  flip.data_bit = 6;
  FailoverSupervisor* plain = nullptr;
  emulate({flip}, plain);
  EXPECT_TRUE(plain->troubles().empty());
  Protection checksums;
  checksums.link_checksums = true;
  FailoverSupervisor* checked = nullptr;
  const CycleEmulation run = emulate({flip}, checked, checksums);
  ASSERT_EQ(checked->troubles().size(), 1U);
  EXPECT_EQ(checked->troubles()[0].module, "module1");
  EXPECT_EQ(checked->troubles()[0].trouble, nav_program::LinkTrouble::checksum);
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 1);
  EXPECT_TRUE(same_path(run, golden()));
}

} // namespace
} // namespace marsokhod::overswitch
