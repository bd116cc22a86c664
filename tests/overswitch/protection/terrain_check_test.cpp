// The navigation's terrain check: range sends a word sum of each row of the terrain it makes,
// and zones and path check a row each time they rebuild it. An upset in the kept terrain then
// halts its module before the zones or the path are made from it, and the cycle restarted on a
// spare gives the fault-free path; without the check the struck terrain is planned on.

#include "overswitch/onboard_cycle.hpp"

#include <gtest/gtest.h>

namespace marsokhod::overswitch {
namespace {

using namespace test;

class TerrainCheckTest : public OnboardCycle {
protected:
  /// An upset in zones' copy of the seeable disparity just after zones took it: zones reads
  /// every row of the terrain at least once after that.
  static Fault upset_in_kept_terrain() {
    Fault f = fault(Fault::Kind::upset, "module1", kUs, "zones");
    f.memory.buffer = "seeable disparity";
    return f;
  }
  static Protection terrain_check() {
    Protection p;
    p.terrain_check = true;
    return p;
  }
};

TEST_F(TerrainCheckTest, StruckKeptTerrainHaltsItsModuleAndTheSpareGivesTheFaultFreePath) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({upset_in_kept_terrain()}, supervisor, terrain_check());
  const InjectedFault& struck = supervisor->injected().at(0);
  ASSERT_TRUE(struck.hit);
  EXPECT_TRUE(struck.hit->corrupts_data());
  ASSERT_EQ(run.halts.size(), 1U);
  EXPECT_EQ(run.halts[0].node, "module1");
  EXPECT_EQ(run.halts[0].process, "zones");
  EXPECT_NE(run.halts[0].cause.find("its sum no longer checks"), std::string::npos)
      << run.halts[0].cause;
  EXPECT_GE(run.halts[0].time, struck.at);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  EXPECT_EQ(supervisor->overswitch().failovers()[0].failed, "module1");
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(TerrainCheckTest, WithoutTheCheckTheStruckTerrainIsPlannedOn) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({upset_in_kept_terrain()}, supervisor);
  EXPECT_EQ(supervisor->injected().at(0).effect, "data corrupted");
  EXPECT_TRUE(run.halts.empty());
  EXPECT_TRUE(supervisor->overswitch().failovers().empty());
  EXPECT_TRUE(run.finished);
}

// The check costs time (range's sums, a sum for each row rebuilt) and changes nothing else.
TEST_F(TerrainCheckTest, CheckLengthensTheCycleAndLeavesItsProducts) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation checked = emulate({}, supervisor, terrain_check());
  ASSERT_TRUE(checked.finished);
  EXPECT_TRUE(checked.halts.empty());
  EXPECT_GT(checked.emulated, golden().emulated);
  EXPECT_TRUE(same_path(checked, golden()));
  EXPECT_EQ(checked.telemetry, golden().telemetry);
}

} // namespace
} // namespace marsokhod::overswitch
