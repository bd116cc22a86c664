// Each process keeps its own floating-point rounding mode and masks across switches.

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <gtest/gtest.h>

#include <cfenv>
#include <vector>

namespace marsokhod::emulator {
namespace {

/// The quotient 1/3 in the current rounding mode, once through SSE (double) and once through
/// the x87 unit (long double), so that MXCSR and the x87 control word are both observed.
struct Thirds {
  double sse = 0;
  long double x87 = 0;
  bool operator==(const Thirds&) const = default;
};

Thirds thirds() {
  volatile double one = 1.0;
  volatile long double one_x87 = 1.0L;
  return Thirds{one / 3.0, one_x87 / 3.0L};
}

Thirds thirds_rounded(int mode) {
  const int saved = std::fegetround();
  std::fesetround(mode);
  const Thirds result = thirds();
  std::fesetround(saved);
  return result;
}

struct Gate : WaitTarget {
  std::string describe() const override { return "gate"; }
};

// The floating-point control words are callee-saved: a process that blocks in one rounding
// mode must resume in it, whatever mode the processes that ran meanwhile chose.
TEST(KernelRounding, EachProcessResumesInItsOwnRoundingMode) {
  const Thirds upward = thirds_rounded(FE_UPWARD);
  const Thirds downward = thirds_rounded(FE_DOWNWARD);
  ASSERT_NE(upward.sse, downward.sse);
  ASSERT_NE(upward.x87, downward.x87);

  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  Gate gate;
  Process* up_process = nullptr;
  Process* down_process = nullptr;
  std::vector<bool> up_kept;
  std::vector<bool> down_kept;
  constexpr int kRounds = 5;
  // Each hands the CPU to the other straight from its fiber: wake the partner, then block.
  up_process = &kernel.spawn(cpu, "up", [&] {
    std::fesetround(FE_UPWARD);
    for (int i = 0; i < kRounds; ++i) {
      kernel.block(WaitInfo{WaitKind::other, &gate});
      up_kept.push_back(std::fegetround() == FE_UPWARD && thirds() == upward);
      kernel.wake(*down_process);
    }
  });
  down_process = &kernel.spawn(cpu, "down", [&] {
    std::fesetround(FE_DOWNWARD);
    for (int i = 0; i < kRounds; ++i) {
      kernel.wake(*up_process);
      kernel.block(WaitInfo{WaitKind::other, &gate});
      down_kept.push_back(std::fegetround() == FE_DOWNWARD && thirds() == downward);
    }
    kernel.wake(*up_process);
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(up_kept, std::vector<bool>(kRounds, true));
  EXPECT_EQ(down_kept, std::vector<bool>(kRounds, true));
  // The kernel's own loop is a context too: it gets its mode back.
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

} // namespace
} // namespace marsokhod::emulator
