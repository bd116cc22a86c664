// Each outcome class of a fault run from a hand-built run whose class is clear by construction,
// the order the classes are decided in, and the figures judged beside the class.

#include "marsokhod/eval/faults/fault_verdict.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;
using nav_program::CycleEmulation;

constexpr emu::Tick kSecond = emu::kSecond;

/// A cycle that found the path through `pixels`, ended at `end` and uploaded `telemetry`.
CycleEmulation finished_cycle(std::vector<nav::PixelPoint> pixels, emu::Tick end,
                              std::vector<std::vector<std::byte>> telemetry) {
  CycleEmulation run;
  run.finished = true;
  run.emulated = end;
  run.result.emplace();
  run.result->plan.found = true;
  run.result->plan.pixels.assign(pixels.begin(), pixels.end());
  run.telemetry = std::move(telemetry);
  return run;
}

std::vector<std::byte> bytes(std::initializer_list<int> values) {
  std::vector<std::byte> out;
  for (const int v : values)
    out.push_back(static_cast<std::byte>(v));
  return out;
}

/// The fault-free run every test judges against: the path (0,0)..(0,2), ended at 20 s, two
/// uploads; its path is safe.
GoldenRun golden() {
  return {finished_cycle({{0, 0}, {0, 1}, {0, 2}}, 20 * kSecond, {bytes({1, 2}), bytes({3})}),
          false};
}

overswitch::InjectedFault hang_at(const std::string& module, emu::Tick at) {
  overswitch::InjectedFault fault;
  fault.fault.kind = overswitch::Fault::Kind::hang;
  fault.fault.module = module;
  fault.at = at;
  return fault;
}

/// A run with the golden path and uploads, nothing seen by the overswitch.
struct Scenario {
  CycleEmulation cycle = golden().run;
  std::vector<overswitch::Failover> failovers;
  std::vector<overswitch::InjectedFault> injected;
  std::vector<overswitch::ReportedTrouble> troubles;
  std::optional<std::string> error;
  bool crosses = false;

  FaultVerdict judge(const GoldenRun& against = golden()) const {
    return judge_fault_run(against, SupervisedRun{&cycle, failovers, injected, troubles, error},
                           crosses);
  }
};

TEST(OutcomeClass, MaskedIsTheGoldenPathWithNoFailoverAndNoRestart) {
  Scenario s;
  s.injected = {hang_at("module1", 25 * kSecond)}; // after the cycle ended: it stopped nothing
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::masked);
  EXPECT_TRUE(v.path_equals_golden);
  EXPECT_FALSE(v.activated);
  EXPECT_FALSE(v.detected);
  EXPECT_FALSE(v.telemetry_lost);
  EXPECT_TRUE(v.reason.empty());
}

TEST(OutcomeClass, RecoveredIsTheGoldenPathAfterAFailover) {
  Scenario s;
  s.injected = {hang_at("module1", 1 * kSecond)};
  s.failovers = {
      {"module1", "module2", "module0", 1200 * emu::kMillisecond, 1212 * emu::kMillisecond, true}};
  s.cycle.restarts = 1;
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::recovered);
  EXPECT_TRUE(v.activated);
  EXPECT_TRUE(v.detected);
  // Found 0.2 s after the hang; the pair whole 12 ms after it was found.
  ASSERT_TRUE(v.detection_latency_s);
  EXPECT_NEAR(*v.detection_latency_s, 0.2, 1e-12);
  ASSERT_TRUE(v.recovery_s);
  EXPECT_NEAR(*v.recovery_s, 0.012, 1e-12);
  ASSERT_EQ(v.failovers.size(), 1U);
  EXPECT_EQ(v.failovers[0], (FailoverFigure{"module1", "module2", 0.012}));
  EXPECT_EQ(v.restarts, 1);
}

TEST(OutcomeClass, RecoveredAlsoAfterARestartOnTheSamePair) {
  Scenario s;
  s.cycle.restarts = 1;
  EXPECT_EQ(s.judge().outcome, Outcome::recovered);
}

TEST(OutcomeClass, SafeStopIsACycleTheOverswitchAbandoned) {
  Scenario s;
  s.cycle.finished = false;
  s.cycle.abandoned = "no spare left to pair with module0";
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::safe_stop);
  EXPECT_EQ(v.reason, "no spare left to pair with module0");
  EXPECT_FALSE(v.path_equals_golden);
  EXPECT_TRUE(v.telemetry_lost);
}

TEST(OutcomeClass, SdcSafeIsAnotherPathThatMissesEveryObstacle) {
  Scenario s;
  s.cycle.result->plan.pixels.back() = {1, 2};
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::sdc_safe);
  EXPECT_FALSE(v.path_equals_golden);
  EXPECT_FALSE(v.unsafe);
}

TEST(OutcomeClass, UnsafeIsAPathIntoAnObstacleWhereTheGoldenOneMissedThem) {
  Scenario s;
  s.cycle.result->plan.pixels.back() = {1, 2};
  s.crosses = true;
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::unsafe);
  EXPECT_TRUE(v.unsafe);
  EXPECT_FALSE(v.golden_unsafe);
}

TEST(OutcomeClass, AnUnsafeGoldenPathIsTheNavigationsOwnErrorNotTheFaults) {
  GoldenRun unsafe_golden = golden();
  unsafe_golden.unsafe = true;
  Scenario s;
  s.crosses = true; // the same path, as unsafe as the golden one
  const FaultVerdict v = s.judge(unsafe_golden);
  EXPECT_EQ(v.outcome, Outcome::masked);
  EXPECT_TRUE(v.unsafe);
  EXPECT_TRUE(v.golden_unsafe);
}

TEST(OutcomeClass, HangIsACycleThatNeitherEndedNorWasAbandoned) {
  Scenario s;
  s.cycle.finished = false;
  s.cycle.emulated = 600 * kSecond;
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::hang);
  EXPECT_EQ(v.reason, "the cycle did not end and no watchdog ran out");
  EXPECT_DOUBLE_EQ(v.delay_s, 580.0);
}

TEST(OutcomeClass, ErrorIsAFaultThatNamedNothingOfTheRun) {
  Scenario s;
  s.error = "fault seu:module0@matching: no block matches 'nothing'";
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::error);
  EXPECT_EQ(v.reason, *s.error);
}

TEST(OutcomeClass, ErrorIsAlsoAMemoryFaultThatEndedTheRun) {
  Scenario s;
  s.cycle.finished = false;
  s.cycle.memory_fault = nav_program::MemoryFaultFigures{"module1", "zones", 65536, "zone map"};
  const FaultVerdict v = s.judge();
  EXPECT_EQ(v.outcome, Outcome::error);
  EXPECT_EQ(v.reason, "memory fault on module1 in zones");
}

// docs/faults.md decides error, safe_stop, hang, unsafe, sdc_safe, then masked or recovered.
TEST(OutcomeClass, TheClassesAreDecidedInTheDocumentedOrder) {
  Scenario error_and_stop;
  error_and_stop.error = "no such module";
  error_and_stop.cycle.finished = false;
  error_and_stop.cycle.abandoned = "no pair";
  EXPECT_EQ(error_and_stop.judge().outcome, Outcome::error);

  Scenario stop_not_hang;
  stop_not_hang.cycle.finished = false;
  stop_not_hang.cycle.abandoned = "no pair";
  EXPECT_EQ(stop_not_hang.judge().outcome, Outcome::safe_stop);

  Scenario unsafe_after_failover;
  unsafe_after_failover.crosses = true;
  unsafe_after_failover.failovers = {{"module1", "module2", "module0", kSecond, 0, false}};
  EXPECT_EQ(unsafe_after_failover.judge().outcome, Outcome::unsafe);
}

TEST(FaultVerdict, TelemetryIsLostUnlessTheGoldenUploadsCameLastByteForByte) {
  Scenario more_before;
  more_before.cycle.telemetry.insert(more_before.cycle.telemetry.begin(), bytes({9}));
  EXPECT_FALSE(more_before.judge().telemetry_lost);

  Scenario changed;
  changed.cycle.telemetry.back() = bytes({4});
  EXPECT_TRUE(changed.judge().telemetry_lost);
}

TEST(FaultVerdict, AnUploadFromAHungModuleIsAFailedModuleCommandingTheWheels) {
  Scenario s;
  s.injected = {hang_at("module1", 5 * kSecond)};
  s.cycle.uploads = {{4 * kSecond, "module1", 12}, {19 * kSecond, "module0", 8}};
  EXPECT_FALSE(s.judge().wheels_commanded_while_failed);
  s.cycle.uploads.push_back({6 * kSecond, "module1", 8});
  EXPECT_TRUE(s.judge().wheels_commanded_while_failed);
}

TEST(FaultVerdict, ALinkTroubleFoundBeforeTheWatchdogSetsTheLatency) {
  Scenario s;
  s.injected = {hang_at("module1", 2 * kSecond)};
  s.troubles = {
      {2100 * emu::kMillisecond, "module0", 0, "module1", nav_program::LinkTrouble::timeout}};
  s.failovers = {
      {"module1", "module2", "module0", 2200 * emu::kMillisecond, 2210 * emu::kMillisecond, true}};
  const FaultVerdict v = s.judge();
  ASSERT_TRUE(v.detection_latency_s);
  EXPECT_NEAR(*v.detection_latency_s, 0.1, 1e-12);
  ASSERT_EQ(v.link_troubles.size(), 1U);
  EXPECT_EQ(v.link_troubles[0].trouble, nav_program::to_string(nav_program::LinkTrouble::timeout));
}

TEST(FaultVerdict, AnUnchangedRunIsTheGoldenOneMaskedAndSeenOnlyByTheEdac) {
  const FaultVerdict corrected = judge_unchanged_run(golden(), true);
  EXPECT_EQ(corrected.outcome, Outcome::masked);
  EXPECT_TRUE(corrected.detected);
  EXPECT_FALSE(corrected.activated);
  EXPECT_TRUE(corrected.path_equals_golden);
  EXPECT_DOUBLE_EQ(corrected.emulated_s, 20.0);
  EXPECT_FALSE(judge_unchanged_run(golden(), false).detected);
}

TEST(OutcomeNames, EveryClassHasOneNameThatReadsBack) {
  EXPECT_EQ(kOutcomes.size(), 7U);
  for (const Outcome outcome : kOutcomes)
    EXPECT_EQ(parse_outcome(to_string(outcome)), outcome);
  EXPECT_STREQ(to_string(Outcome::sdc_safe), "sdc_safe");
  EXPECT_FALSE(parse_outcome("Masked"));
}

} // namespace
} // namespace marsokhod::eval
