// PAR and PRI PAR: startp/endp costs, joins, priorities and killing.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::Priority;
using emulator::StopReason;
using emulator::Tick;
using testing::OccamRig;

TEST(Par, ReturnsAfterEveryBranchAndChargesStartpAndEndp) {
  OccamRig rig;
  Tick parent_done = -1;
  rig.spawn("parent", [&] {
    par([&] { compute(emulator::Instruction::ldc, 100); },
        [&] { compute(emulator::Instruction::ldc, 100); },
        [&] { compute(emulator::Instruction::ldc, 100); });
    parent_done = rig.kernel.now();
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  // One CPU: startp for the two started branches (12 each), 3 x 100 ldc (1 cycle each),
  // endp at the end of every branch (13 each).
  EXPECT_EQ(parent_done, rig.cycles(2 * 12 + 3 * 100 + 3 * 13));
}

TEST(Par, ReplicatedParRunsEveryIndexOnce) {
  OccamRig rig;
  std::vector<int> hits(8, 0);
  rig.spawn("parent", [&] { par_for(8, [&](std::size_t i) { ++hits[i]; }); });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(hits, std::vector<int>(8, 1));
}

TEST(Par, BranchesCommunicateAndNestedParsJoin) {
  OccamRig rig;
  Chan<int> c("c");
  int sum = 0;
  rig.spawn("parent", [&] {
    par(
        [&] {
          for (int i = 1; i <= 4; ++i)
            c << i;
        },
        [&] {
          int x = 0;
          for (int i = 0; i < 4; ++i) {
            c >> x;
            sum += x;
          }
          par([] {}, [] {});
        });
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(sum, 10);
}

TEST(Par, PriParHighBranchPreemptsLowAfterTheEventLatency) {
  OccamRig rig;
  Tick high_resumed = -1;
  Tick low_done = -1;
  rig.spawn("parent", [&] {
    pri_par(
        [&] {
          Timer tim;
          tim.wait_after(9); // high clock: wakes when it reads 10, at 10 us
          high_resumed = rig.kernel.now();
        },
        [&] {
          compute(emulator::Instruction::ldc, 10'000);
          low_done = rig.kernel.now();
        });
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  // Event latency: 19 cycles from the timer to the high process running (data book).
  EXPECT_EQ(high_resumed, emulator::microseconds(10) + rig.cycles(19));
  // The low branch: startp 12, then the high branch's tin (wait) 30 takes the CPU first; its
  // own 10,000 cycles; interrupted for the latency 19 plus the high branch's endp 13.
  EXPECT_EQ(low_done, rig.cycles(12 + 30 + 10'000 + 19 + 13));
}

TEST(Par, KillingTheParentKillsItsBranches) {
  OccamRig rig;
  int unwound = 0;
  struct Count {
    int* n;
    ~Count() { ++*n; }
  };
  emulator::Process& parent = rig.spawn("parent", [&] {
    Chan<int> never("never");
    par(
        [&] {
          Count c{&unwound};
          int x = 0;
          never >> x;
        },
        [&] {
          Count c{&unwound};
          Timer().wait_after(1'000'000);
        });
  });
  rig.kernel.run_for(emulator::milliseconds(1));
  EXPECT_EQ(rig.kernel.live_processes(), 2U);
  rig.kernel.kill(parent);
  EXPECT_EQ(unwound, 2);
  EXPECT_EQ(rig.kernel.live_processes(), 0U);
}

TEST(Par, WorkspaceIsChargedToNodeMemoryWhileTheBranchLives) {
  OccamRig rig;
  std::size_t in_use_during = 0;
  std::size_t in_use_before = 0;
  rig.spawn("parent", [&] {
    in_use_before = rig.node.memory().usage().in_use_bytes;
    ParOptions options;
    options.workspace_bytes = 256;
    const std::vector<std::function<void()>> branches = {
        [&] { in_use_during = rig.node.memory().usage().in_use_bytes; }, [] {}};
    par(branches, options);
  });
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  EXPECT_EQ(in_use_during, in_use_before + 256); // one started branch
  EXPECT_EQ(rig.node.memory().usage().in_use_bytes, in_use_before);
}

} // namespace
} // namespace marsokhod::occam_port
