// Commstime: each loop costs the sum of its processes' data-book instructions.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/commstime.hpp"

#include <gtest/gtest.h>

namespace marsokhod::occam_port {
namespace {

using emulator::StopReason;
using testing::OccamRig;

// Data-book cycles (T805.md, internal memory): a channel operation loads its operands with
// ldlp 1 + ldl 2 + ldc 1 = 4, then in/out of one word take 2*1+19 = 21.
constexpr std::int64_t kChannelOp = 4 + 21;
constexpr std::int64_t kJ = 3;
constexpr std::int64_t kLend = 10;
constexpr std::int64_t kIncrement = 2 + 1 + 1; // ldl, adc, stl
constexpr std::int64_t kPrefix = 2 * kChannelOp + kJ;
constexpr std::int64_t kSuccessor = 2 * kChannelOp + kIncrement + kJ;
constexpr std::int64_t kConsumer = kChannelOp + kLend;

TEST(Commstime, SeqDeltaLoopIsTheSumOfItsInstructions) {
  OccamRig rig;
  CommstimeOptions options;
  options.loops = 500;
  options.parallel_delta = false;
  CommstimeResult result;
  spawn_commstime(rig.node, options, result);
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  // One processor runs all four processes, so a loop costs the sum of their work.
  const std::int64_t delta = 3 * kChannelOp + kJ;
  const std::int64_t loop = kPrefix + delta + kSuccessor + kConsumer; // 223 cycles
  EXPECT_EQ(result.measured_time, rig.cycles(loop * options.loops));
  EXPECT_EQ(result.communications, 4 * (options.loops + 2 * options.warmup_loops));
}

TEST(Commstime, ParDeltaAddsOneStartpAndTwoEndp) {
  OccamRig rig;
  CommstimeOptions options;
  options.loops = 500;
  CommstimeResult result;
  spawn_commstime(rig.node, options, result);
  EXPECT_EQ(rig.kernel.run().reason, StopReason::finished);
  const std::int64_t delta = 3 * kChannelOp + kJ + 12 + 2 * 13;       // startp 12, endp 13 each
  const std::int64_t loop = kPrefix + delta + kSuccessor + kConsumer; // 261 cycles
  EXPECT_EQ(result.measured_time, rig.cycles(loop * options.loops));
  EXPECT_NEAR(result.emulated_us_per_loop(), 261 * 0.033333, 1e-9);
}

} // namespace
} // namespace marsokhod::occam_port
