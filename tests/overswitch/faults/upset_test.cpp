// Upsets and stuck bits in the onboard modules' memory: a hit on what the processor runs on sends
// the module astray and its watchdog fails it over; a hit on data reaches the program and nothing
// else; the EDAC corrects a single error and leaves the run as it was, flags a second in the same
// word (the module halts), and its scrubber clears the first before the second comes.

#include "overswitch/onboard_cycle.hpp"

#include <gtest/gtest.h>

namespace marsokhod::overswitch {
namespace {

using namespace test;

class UpsetTest : public OnboardCycle {
protected:
  /// The fault-free cycle with `protection`.
  CycleEmulation protected_golden(const Protection& protection) {
    FailoverSupervisor* unused = nullptr;
    return emulate({}, unused, protection);
  }

  static Fault upset(const std::string& module, Tick at, const std::string& stage = "") {
    return fault(Fault::Kind::upset, module, at, stage);
  }
  static Fault upset_at(const std::string& module, Tick at, emulator::Address address,
                        unsigned bit) {
    Fault f = upset(module, at);
    f.memory.address = address;
    f.memory.bit = bit;
    return f;
  }

  /// The watchdog of a module that stopped at `stopped` runs out 200 ms after its last kick at
  /// or before then (kicks every 100 ms from t = 0), plus at most the kick's latency.
  static void expect_found_one_timeout_after_the_last_kick(const Failover& failover, Tick stopped) {
    const Tick last_kick = stopped / (100 * kMs) * (100 * kMs);
    EXPECT_GE(failover.detected, last_kick + 200 * kMs);
    EXPECT_LE(failover.detected, last_kick + 200 * kMs + kKickLatency);
  }
};

constexpr emulator::Address kExternalBase = emulator::MemoryArena::kExternalBase;
/// The last word of a module's 256 KB of external memory: nothing is allocated there 1 ms into
/// the cycle (first fit fills memory from its bottom).
constexpr emulator::Address kTopWord = kExternalBase + 256 * 1024 - 4;

TEST_F(UpsetTest, HitOnAWorkspaceSendsTheModuleAstrayAndItsWatchdogFailsItOver) {
  Fault hit = upset("module1", 100 * kMs, "refine");
  hit.memory.buffer = "workspace";
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({hit}, supervisor);
  ASSERT_EQ(supervisor->injected().size(), 1U);
  const InjectedFault& struck = supervisor->injected()[0];
  ASSERT_TRUE(struck.hit);
  ASSERT_TRUE(struck.hit->block);
  EXPECT_EQ(struck.hit->block->kind, emulator::BlockKind::workspace);
  EXPECT_TRUE(struck.hit->corrupts_control());
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  EXPECT_EQ(failover.failed, "module1");
  expect_found_one_timeout_after_the_last_kick(failover, struck.at);
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(UpsetTest, StuckBitInTheCodeSendsTheModuleAstray) {
  Fault stuck = fault(Fault::Kind::stuck, "module0", 2050 * kMs);
  stuck.memory.buffer = "code";
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({stuck}, supervisor);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  EXPECT_EQ(supervisor->overswitch().failovers()[0].failed, "module0");
  expect_found_one_timeout_after_the_last_kick(supervisor->overswitch().failovers()[0], 2050 * kMs);
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(UpsetTest, HitOnDataReachesTheProgramAndNoWatchdog) {
  Fault hit = upset("module0", 10 * kMs, "features");
  hit.memory.buffer = "left image";
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({hit}, supervisor);
  const InjectedFault& struck = supervisor->injected().at(0);
  ASSERT_TRUE(struck.hit);
  ASSERT_TRUE(struck.hit->block);
  EXPECT_NE(struck.hit->block->label.find("left image"), std::string::npos);
  EXPECT_TRUE(struck.hit->corrupts_data());
  EXPECT_EQ(struck.effect, "data corrupted");
  EXPECT_TRUE(supervisor->overswitch().failovers().empty());
  EXPECT_TRUE(run.finished);
}

TEST_F(UpsetTest, UpsetInFreeMemoryLeavesTheRunAsItWas) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({upset_at("module0", kMs, kTopWord, 5)}, supervisor);
  const InjectedFault& struck = supervisor->injected().at(0);
  ASSERT_TRUE(struck.hit);
  EXPECT_FALSE(struck.hit->block);
  EXPECT_EQ(struck.effect, "none: free memory");
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.emulated, golden().emulated);
  EXPECT_TRUE(same_path(run, golden()));
  EXPECT_EQ(run.telemetry, golden().telemetry);
}

TEST_F(UpsetTest, BufferNamedByNoBlockIsAnErrorOfTheRun) {
  Fault hit = upset("module0", 100 * kMs);
  hit.memory.buffer = "no such buffer";
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({hit}, supervisor);
  ASSERT_TRUE(supervisor->error());
  EXPECT_NE(supervisor->error()->find("no buffer matching 'no such buffer'"), std::string::npos);
  EXPECT_TRUE(run.abandoned);
}

// Address 7 lies below the on-chip RAM at #80000000, #90000000 above the 256 KB of external
// RAM that ends at #80040FFF: both are outside the module's memory.
TEST_F(UpsetTest, AnAddressOutsideTheModulesMemoryIsAnErrorOfTheRun) {
  for (const emulator::Address address : {emulator::Address{7}, emulator::Address{0x90000000U}}) {
    FailoverSupervisor* supervisor = nullptr;
    const CycleEmulation run = emulate({upset_at("module0", 100 * kMs, address, 0)}, supervisor);
    ASSERT_TRUE(supervisor->error()) << address;
    EXPECT_NE(supervisor->error()->find("is outside its memory (#80000000..#80040FFF)"),
              std::string::npos)
        << *supervisor->error();
    EXPECT_TRUE(run.abandoned);
  }
}

TEST_F(UpsetTest, EdacCorrectsAnUpsetInExternalMemoryAndTheRunIsUnchanged) {
  Protection edac;
  edac.edac = true;
  const CycleEmulation fault_free = protected_golden(edac);
  Fault hit = upset("module0", 10 * kMs, "features");
  hit.memory.buffer = "left image";
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({hit}, supervisor, edac);
  const InjectedFault& struck = supervisor->injected().at(0);
  ASSERT_TRUE(struck.hit);
  EXPECT_FALSE(struck.hit->on_chip);
  EXPECT_EQ(struck.hit->effect, emulator::UpsetEffect::corrected);
  EXPECT_FALSE(struck.hit->corrupts_data());
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.emulated, fault_free.emulated);
  EXPECT_TRUE(same_path(run, fault_free));
  EXPECT_EQ(run.telemetry, fault_free.telemetry);
}

TEST_F(UpsetTest, EdacsWaitStatesLengthenTheCycleAndLeaveItsProducts) {
  Protection edac;
  edac.edac = true;
  const CycleEmulation with = protected_golden(edac);
  ASSERT_TRUE(with.finished);
  // Every external access takes kEdacWaitStates more cycles, and the buffers are external.
  EXPECT_GT(with.emulated, golden().emulated);
  EXPECT_TRUE(same_path(with, golden()));
  EXPECT_EQ(with.telemetry, golden().telemetry);
}

TEST_F(UpsetTest, SecondErrorInAWordUnderEdacHaltsTheModule) {
  Protection edac;
  edac.edac = true;
  FailoverSupervisor* supervisor = nullptr;
  // Two bits of the same word: the EDAC corrects the first and can only flag the second.
  const CycleEmulation run = emulate({upset_at("module1", 500 * kMs, kTopWord, 0),
                                      upset_at("module1", 1250 * kMs, kTopWord + 1, 3)},
                                     supervisor, edac);
  ASSERT_EQ(supervisor->injected().size(), 2U);
  EXPECT_EQ(supervisor->injected()[0].hit->effect, emulator::UpsetEffect::corrected);
  EXPECT_EQ(supervisor->injected()[1].hit->effect, emulator::UpsetEffect::uncorrectable);
  ASSERT_FALSE(run.halts.empty());
  EXPECT_EQ(run.halts[0].node, "module1");
  EXPECT_EQ(run.halts[0].time, 1250 * kMs);
  EXPECT_NE(run.halts[0].cause.find("EDAC"), std::string::npos);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  expect_found_one_timeout_after_the_last_kick(supervisor->overswitch().failovers()[0], 1250 * kMs);
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(UpsetTest, ScrubbingClearsTheFirstErrorBeforeTheSecondComes) {
  Protection scrubbed;
  scrubbed.edac = true;
  scrubbed.scrub_period = 500 * kMs;
  FailoverSupervisor* supervisor = nullptr;
  // A whole pass every 0.5 s: by 1.5 s after the first upset its word has been rewritten.
  const CycleEmulation run = emulate({upset_at("module1", 500 * kMs, kTopWord, 0),
                                      upset_at("module1", 2000 * kMs, kTopWord + 1, 3)},
                                     supervisor, scrubbed);
  ASSERT_EQ(supervisor->injected().size(), 2U);
  EXPECT_EQ(supervisor->injected()[1].hit->effect, emulator::UpsetEffect::corrected);
  EXPECT_TRUE(run.halts.empty());
  EXPECT_TRUE(supervisor->overswitch().failovers().empty());
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
  Protection edac_only;
  edac_only.edac = true;
  // The scrubber takes its share of the CPU.
  EXPECT_GT(run.emulated, protected_golden(edac_only).emulated);
}

TEST(Protection, EdacAddsItsWaitStatesToTheModulesUnderTheOverswitchOnly) {
  const emulator::PlatformSpec onboard = emulator::load_platform(kPlatforms / "onboard.toml");
  Protection edac;
  edac.edac = true;
  const emulator::PlatformSpec with = protected_platform(onboard, edac);
  for (std::size_t i = 0; i < onboard.nodes.size(); ++i)
    EXPECT_EQ(with.nodes[i].cpu.costs.wait_states,
              onboard.nodes[i].cpu.costs.wait_states + kEdacWaitStates)
        << onboard.nodes[i].name;
  const emulator::PlatformSpec card = emulator::load_platform(kPlatforms / "pc-card.toml");
  EXPECT_EQ(protected_platform(card, edac).nodes[0].cpu.costs.wait_states,
            card.nodes[0].cpu.costs.wait_states);
}

} // namespace
} // namespace marsokhod::overswitch
