// Tests: the emulated computer's fault during a traverse, failed over by the overswitch, with
// the cycle's path and time checked against the same course without the fault.

#include "marsokhod/eval/traverse/traverse.hpp"
#include "marsokhod/eval/traverse/traverse_faults.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace marsokhod::eval {
namespace {

const std::string& hang_power() {
  static const std::string file =
      (std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "campaigns" / "hang-power.toml").string();
  return file;
}

// The first seed from `from` whose course meets its fault in cycle 0.
std::uint64_t seed_struck_at_once(std::uint64_t from) {
  for (std::uint64_t seed = from;; ++seed)
    if (TraverseFaults(hang_power(), seed).fault_cycle() == 0)
      return seed;
}

TraverseSettings onboard_course(std::uint64_t seed) {
  TraverseSettings s;
  s.seed = seed;
  s.rocks = 0.0;
  s.slope_deg = 0.0;
  s.goal_m = 10.0;
  s.platform = "onboard";
  s.image_px = 128;
  s.max_cycles = 1;
  return s;
}

// A hang or a power loss of one of the pair in the first cycle: the overswitch fails it over,
// the spare's restarted cycle gives the fault-free path, and the cycle takes its fault-free time
// plus the time the fault cost (the supervision's heartbeats add well under 2 % to a cycle).
TEST(TraverseFaults, TheFailoverGivesTheFaultFreePathAndCostsTime) {
  const std::uint64_t seed = seed_struck_at_once(1);
  const TraverseResult plain = run_traverse(onboard_course(seed));
  TraverseSettings s = onboard_course(seed);
  s.faults_file = hang_power();
  const TraverseResult struck = run_traverse(s);
  ASSERT_EQ(struck.faults.size(), 1u);
  const TraverseFault& fault = struck.faults.front();
  EXPECT_EQ(fault.cycle, 0);
  EXPECT_EQ(fault.outcome, "recovered") << fault.fault;
  EXPECT_TRUE(fault.recovered);
  EXPECT_GE(fault.failovers, 1);
  EXPECT_GT(fault.time_lost_s, 0.0);
  ASSERT_EQ(struck.cycles.size(), 1u);
  ASSERT_EQ(plain.cycles.size(), 1u);
  EXPECT_EQ(struck.cycles[0].planned, plain.cycles[0].planned);
  EXPECT_EQ(struck.cycles[0].track, plain.cycles[0].track);
  EXPECT_NEAR(struck.cycles[0].compute_seconds - fault.time_lost_s, plain.cycles[0].compute_seconds,
              0.02 * plain.cycles[0].compute_seconds);
  EXPECT_NE(struck.cycles[0].events.front().find("fault: "), std::string::npos);
}

TEST(TraverseFaults, TheFaultsCycleIsDrawnFromTheSeedOverTheFirstCycles) {
  int seen[kFaultCycles] = {};
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const int cycle = TraverseFaults(hang_power(), seed).fault_cycle();
    ASSERT_GE(cycle, 0);
    ASSERT_LT(cycle, kFaultCycles);
    ++seen[cycle];
    EXPECT_EQ(TraverseFaults(hang_power(), seed).fault_cycle(), cycle) << "seed " << seed;
  }
  for (int c = 0; c < kFaultCycles; ++c)
    EXPECT_GT(seen[c], 10) << "cycle " << c; // 25 expected of 200
}

TEST(TraverseFaults, FaultsNeedTheCampaignsEmulatedPlatform) {
  TraverseSettings s = onboard_course(1);
  s.faults_file = hang_power();
  s.platform = "native";
  EXPECT_THROW(validate(s), std::invalid_argument);
  s.platform = "pc-card";
  try {
    run_traverse(s);
    ADD_FAILURE() << "a pc-card course ran the onboard campaign";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("runs on 'onboard'"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace marsokhod::eval
