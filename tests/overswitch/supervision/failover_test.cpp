// The overswitch on the onboard computer: a hang or a power loss is found by its watchdog at
// the time the platform's constants give, a spare boots over a link in the time its code takes
// on the wire, and the restarted cycle plans the fault-free path; with nothing left to form a
// pair, a safe stop.

#include "overswitch/onboard_cycle.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace marsokhod::overswitch {
namespace {

using namespace test;

class FailoverTest : public OnboardCycle {};

TEST_F(FailoverTest, FaultFreeRunFinishesWithoutAnOverswitchEvent) {
  const CycleEmulation& run = golden();
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 0);
  ASSERT_TRUE(run.result);
  EXPECT_TRUE(run.result->plan.found);
  EXPECT_FALSE(run.abandoned);
}

TEST_F(FailoverTest, HangIsFoundOneTimeoutAfterTheLastKickAndTheSpareBootsInItsStreamTime) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs)}, supervisor);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  // Kicks every 100 ms from t = 0: the last before the hang is at 1.0 s; 200 ms later the
  // watchdog runs out.
  EXPECT_GE(failover.detected, 1200 * kMs);
  EXPECT_LE(failover.detected, 1200 * kMs + kKickLatency);
  EXPECT_EQ(failover.failed, "module1");
  EXPECT_EQ(failover.spare, "module2");
  EXPECT_EQ(failover.booted_from, "module0");
  ASSERT_TRUE(failover.ok);
  const Tick boot = failover.booted - failover.detected;
  const Tick expected = boot_time_of("module1");
  EXPECT_GE(boot, expected);
  EXPECT_LE(boot, expected + expected / 100) << "boot " << boot << " ps, stream " << expected;
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 1);
  EXPECT_TRUE(same_path(run, golden()));
  for (const nav_program::DeviceUpload& upload : run.uploads)
    EXPECT_NE(upload.node, "module1") << "an upload from the hung module";
}

TEST_F(FailoverTest, PowerLossAtANamedStageMovesThatModulesShareToTheSpare) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run =
      emulate({fault(Fault::Kind::power_loss, "module0", 500 * kMs, "matching")}, supervisor);
  ASSERT_EQ(supervisor->injected().size(), 1U);
  const Tick lost = supervisor->injected()[0].at;
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  // The watchdog runs out 200 ms after the last kick at or before the loss.
  const Tick last_kick = lost / (100 * kMs) * (100 * kMs);
  EXPECT_GE(failover.detected, last_kick + 200 * kMs);
  EXPECT_LE(failover.detected, last_kick + 200 * kMs + kKickLatency);
  EXPECT_EQ(failover.spare, "module2");
  EXPECT_EQ(failover.booted_from, "module1");
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
  const auto& processes = run.processes;
  const auto acquire = std::find_if(processes.begin(), processes.end(),
                                    [](const auto& p) { return p.name == "acquire"; });
  ASSERT_NE(acquire, processes.end());
  EXPECT_EQ(acquire->node, "module2");
}

TEST_F(FailoverTest, WithEverySpareUsedTheOverswitchStopsSafely) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1000 * kMs),
                                      fault(Fault::Kind::hang, "module2", 2000 * kMs),
                                      fault(Fault::Kind::hang, "module3", 3000 * kMs)},
                                     supervisor);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 3U);
  EXPECT_EQ(failovers[1].spare, "module3");
  EXPECT_TRUE(failovers[2].spare.empty());
  // module3 kicks every 100 ms from its boot: its last kick before 3 s, then the timeout.
  const Tick booted = failovers[1].booted;
  const Tick last_kick = booted + (3000 * kMs - booted) / (100 * kMs) * (100 * kMs);
  EXPECT_GE(failovers[2].detected, last_kick + 200 * kMs);
  EXPECT_LE(failovers[2].detected, last_kick + 200 * kMs + kKickLatency);
  EXPECT_TRUE(supervisor->overswitch().safe_stopped());
  EXPECT_FALSE(run.finished);
  ASSERT_TRUE(run.abandoned);
  EXPECT_EQ(run.emulated, failovers[2].detected);
}

TEST_F(FailoverTest, PartnerFailingDuringTheBootLeavesNothingToBootFrom) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs),
                                      fault(Fault::Kind::hang, "module0", 1205 * kMs)},
                                     supervisor);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 2U);
  EXPECT_FALSE(failovers[0].ok); // module0 died while sending module2 its code
  EXPECT_EQ(failovers[1].failed, "module0");
  // module0's last kick was at 1.2 s.
  EXPECT_GE(failovers[1].detected, 1400 * kMs);
  EXPECT_LE(failovers[1].detected, 1400 * kMs + kKickLatency);
  EXPECT_TRUE(supervisor->overswitch().safe_stopped());
  EXPECT_FALSE(run.finished);
}

TEST_F(FailoverTest, SpareThatDoesNotBootIsFailedAfterItsAllowanceAndTheNextOneTaken) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs),
                                      fault(Fault::Kind::hang, "module2", 1201 * kMs)},
                                     supervisor);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 2U);
  EXPECT_EQ(failovers[1].failed, "module2");
  EXPECT_EQ(failovers[1].spare, "module3");
  // The allowance (1 s) runs from module2's power-on, when module1 was found failed.
  EXPECT_EQ(failovers[1].detected, failovers[0].detected + 1000 * kMs);
  ASSERT_TRUE(failovers[1].ok);
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(FailoverTest, LeakHaltsTheModuleAtItsNextBufferAndItsWatchdogFailsItOver) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run =
      emulate({fault(Fault::Kind::leak, "module1", 100 * kMs, "zones")}, supervisor);
  // The leak takes module1's free memory; the next buffer there fails and the module halts
  // (HaltOnError); its heartbeat stops with it.
  ASSERT_EQ(run.halts.size(), 1U);
  EXPECT_EQ(run.halts[0].node, "module1");
  EXPECT_GE(run.halts[0].time, supervisor->injected().at(0).at);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  const Tick halted = run.halts[0].time;
  const Tick last_kick = halted / (100 * kMs) * (100 * kMs);
  EXPECT_GE(failover.detected, last_kick + 200 * kMs);
  EXPECT_LE(failover.detected, last_kick + 200 * kMs + kKickLatency);
  EXPECT_EQ(failover.spare, "module2");
  ASSERT_TRUE(run.finished);
  EXPECT_FALSE(run.memory_fault);
  EXPECT_TRUE(same_path(run, golden()));
}

} // namespace
} // namespace marsokhod::overswitch
