// The mission state across a failover: the cycle goes on from the state the last cycle left,
// a spare takes the survivor's copy with its boot stream, and a copy struck by an upset is
// refused rather than driven on.

#include "overswitch/onboard_cycle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace marsokhod::overswitch {
namespace {

using namespace test;

/// After an emergency stop the rover turned 30 degrees left and looks for a short path; it has
/// made 8 cycles (5 uploads each) and stands 4 m out, heading 12 degrees.
nav_program::MissionState escaping() {
  nav_program::MissionState state;
  state.motion.state = nav::MotionState::escape_planning;
  state.motion.turned_deg = 30.0;
  state.motion.turn_sign = 1.0;
  state.x_m = 4.0;
  state.heading_deg = 12.0;
  state.uploads = 40;
  return state;
}

/// The motion state telemetry sent the ground: its fourth upload, one INT32.
std::int32_t reported_state(const CycleEmulation& run) {
  const auto& uploads = run.telemetry;
  EXPECT_GE(uploads.size(), 5U);
  std::int32_t state = -1;
  if (uploads.size() >= 5 && uploads[uploads.size() - 2].size() == 4)
    std::memcpy(&state, uploads[uploads.size() - 2].data(), 4);
  return state;
}

class MissionStateTest : public OnboardCycle {
protected:
  CycleEmulation escaping_golden() {
    mission_ = escaping();
    FailoverSupervisor* unused = nullptr;
    return emulate({}, unused);
  }
};

TEST_F(MissionStateTest, TheCycleGoesOnFromTheStateTheLastCycleLeft) {
  const CycleEmulation run = escaping_golden();
  ASSERT_TRUE(run.finished);
  ASSERT_TRUE(run.mission_after);
  ASSERT_TRUE(run.result && run.result->plan.found);
  // Paper, section 3: escape planning that finds its short path drives it.
  EXPECT_EQ(run.mission_after->motion.state, nav::MotionState::escape_driving);
  EXPECT_EQ(reported_state(run), static_cast<std::int32_t>(nav::MotionState::escape_driving));
  // From rest, the same path is a normal one.
  EXPECT_EQ(reported_state(golden()), static_cast<std::int32_t>(nav::MotionState::normal_driving));
  EXPECT_EQ(run.mission_after->uploads, 45U);
  // Dead reckoning over the wheel commands (the last upload: turn and distance, two doubles
  // each): each turns on the spot, then drives straight.
  const std::vector<std::byte>& wheels = run.telemetry.back();
  ASSERT_EQ(wheels.size() % 16, 0U);
  ASSERT_GT(wheels.size(), 0U);
  double heading = 12.0;
  double x = 4.0;
  double y = 0.0;
  for (std::size_t i = 0; i < wheels.size(); i += 16) {
    double turn = 0.0;
    double distance = 0.0;
    std::memcpy(&turn, wheels.data() + i, 8);
    std::memcpy(&distance, wheels.data() + i + 8, 8);
    heading += turn;
    x += distance * std::cos(heading * M_PI / 180.0);
    y += distance * std::sin(heading * M_PI / 180.0);
  }
  // The modules keep the pose as REAL32.
  EXPECT_NEAR(run.mission_after->heading_deg, heading, 1e-3);
  EXPECT_NEAR(run.mission_after->x_m, x, 1e-4);
  EXPECT_NEAR(run.mission_after->y_m, y, 1e-4);
}

TEST_F(MissionStateTest, ASpareGoesOnFromTheSurvivorsCopy) {
  const CycleEmulation fault_free = escaping_golden();
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs)}, supervisor);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  ASSERT_TRUE(run.finished);
  ASSERT_TRUE(run.mission_after);
  EXPECT_EQ(*run.mission_after, *fault_free.mission_after);
  EXPECT_EQ(reported_state(run), reported_state(fault_free));
}

TEST_F(MissionStateTest, ACopyStruckByAnUpsetIsRefusedAndTheModuleFailsOver) {
  const CycleEmulation fault_free = escaping_golden();
  Fault upset = fault(Fault::Kind::upset, "module1", 100 * kMs);
  upset.memory.buffer = "mission state";
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({upset}, supervisor);
  ASSERT_TRUE(supervisor->injected().at(0).hit);
  EXPECT_TRUE(supervisor->injected()[0].hit->corrupts_data());
  // The path process reads the state at its start: the check word refuses it, the module halts.
  ASSERT_FALSE(run.halts.empty());
  EXPECT_EQ(run.halts[0].node, "module1");
  EXPECT_NE(run.halts[0].cause.find("mission state"), std::string::npos) << run.halts[0].cause;
  ASSERT_TRUE(run.finished);
  ASSERT_TRUE(run.mission_after);
  EXPECT_EQ(*run.mission_after, *fault_free.mission_after);
}

} // namespace
} // namespace marsokhod::overswitch
