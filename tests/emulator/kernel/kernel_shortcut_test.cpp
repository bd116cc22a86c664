// The kernel's shortcuts (compute chunks that only move the clock, direct hand-over of a CPU
// from one process to the next, the inline wake-up) must give exactly what the general path
// gives: these cases sit on the edges where a shortcut has to step aside.

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace marsokhod::emulator {
namespace {

TEST(KernelShortcut, LowProcessThatReadiesAHighOneGivesWayAtItsNextChunk) {
  Kernel kernel;
  CpuTiming timing;
  timing.preemption_latency = nanoseconds(600);
  Cpu& cpu = kernel.add_cpu("node0", timing);
  Tick high_start = -1;
  Tick low_end = -1;
  Process& high = kernel.spawn(
      cpu, "high",
      [&] {
        kernel.block(WaitInfo{});
        high_start = kernel.now();
        kernel.consume(microseconds(2));
      },
      SpawnOptions{Priority::high});
  kernel.spawn(cpu, "low", [&] {
    kernel.consume(microseconds(1));
    kernel.wake(high);
    // The next chunk would fit before any event: it must still yield to high first.
    kernel.consume(microseconds(1));
    low_end = kernel.now();
  });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  // Readied by the running low process itself: no event latency.
  EXPECT_EQ(high_start, microseconds(1));
  EXPECT_EQ(low_end, microseconds(4));
}

TEST(KernelShortcut, TimesliceEndsAtTheFirstBoundaryAfterTwoTicksInSmallChunks) {
  Kernel kernel;
  CpuTiming timing;
  timing.timeslice = microseconds(100);
  timing.slices_before_deschedule = 2;
  Cpu& cpu = kernel.add_cpu("node0", timing);
  std::vector<Tick> a_ends;
  std::vector<Tick> b_ends;
  for (auto* ends : {&a_ends, &b_ends}) {
    kernel.spawn(
        cpu, "worker",
        [&kernel, ends] {
          for (int chunk = 0; chunk < 300; ++chunk) {
            kernel.consume(microseconds(1));
            ends->push_back(kernel.now());
          }
        });
  }
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  // a is granted at 0 and sees the ticks at 100 and 200 us: descheduled at the boundary at
  // 200 us. b, granted at 200, sees 300 and 400 and gives way at 400; a finishes its last
  // 100 chunks by 500, then b its last 100.
  ASSERT_EQ(a_ends.size(), 300U);
  ASSERT_EQ(b_ends.size(), 300U);
  EXPECT_EQ(a_ends[199], microseconds(200));
  EXPECT_EQ(b_ends[0], microseconds(201));
  EXPECT_EQ(b_ends[199], microseconds(400));
  EXPECT_EQ(a_ends[200], microseconds(401));
  EXPECT_EQ(a_ends[299], microseconds(500));
  EXPECT_EQ(b_ends[200], microseconds(501));
  EXPECT_EQ(kernel.now(), microseconds(600));
}

TEST(KernelShortcut, EventsScheduledByTheProcessInterruptItsChunks) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  int chunks = 0;
  std::vector<int> seen;
  kernel.spawn(
      cpu, "worker",
      [&] {
        // An event before the end of the next chunk: that chunk must end through the queue, so
        // that the event sees the work done before it and none after.
        kernel.schedule_at(
            nanoseconds(2'500), event_priority::normal, [&] { seen.push_back(chunks); });
        for (int i = 0; i < 5; ++i) {
          kernel.consume(microseconds(1));
          ++chunks;
        }
      });
  kernel.schedule_at(nanoseconds(3'500), event_priority::normal, [&] { seen.push_back(chunks); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(seen, (std::vector<int>{2, 3}));
  EXPECT_EQ(kernel.now(), microseconds(5));
}

TEST(KernelShortcut, BusyTimeCountsEveryProcessOfAnUnbrokenRun) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  std::vector<Process*> ring;
  for (int i = 0; i < 3; ++i) {
    ring.push_back(&kernel.spawn(
        cpu, "p",
        [&kernel, &ring, i] {
          for (int round = 0; round < 4; ++round) {
            kernel.consume(microseconds(1));
            // Wake the next one and wait: the CPU passes straight from one process to another.
            kernel.wake(*ring[static_cast<std::size_t>((i + 1) % 3)]);
            if (round < 3)
              kernel.block(WaitInfo{});
          }
        }));
  }
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(kernel.now(), microseconds(12));
  EXPECT_EQ(cpu.busy_time(), microseconds(12));
}

} // namespace
} // namespace marsokhod::emulator
