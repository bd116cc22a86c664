// Kernel processes: spawning, blocking, waking, killing and deadlock reports.

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::emulator {
namespace {

/// Names itself in describe(); stands for a channel in the deadlock tests.
struct NamedTarget : WaitTarget {
  explicit NamedTarget(std::string n) : name(std::move(n)) {}
  std::string describe() const override { return name; }
  std::string name;
};

std::string stamp(const std::string& who, Tick t) {
  return fmt::format("{}@{}", who, format_time(t));
}

TEST(KernelProcess, ProcessesOnOneCpuShareItInTurn) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  std::vector<Tick> ends;
  for (int i = 0; i < 2; ++i) {
    kernel.spawn(
        cpu, "worker",
        [&] {
          kernel.consume(microseconds(3));
          ends.push_back(kernel.now());
        });
  }
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  // One processor: the second starts when the first has finished.
  EXPECT_EQ(ends, (std::vector<Tick>{microseconds(3), microseconds(6)}));
  EXPECT_EQ(cpu.busy_time(), microseconds(6));
}

TEST(KernelProcess, ProcessesOnTwoCpusRunConcurrently) {
  Kernel kernel;
  Cpu& a = kernel.add_cpu("node0");
  Cpu& b = kernel.add_cpu("node1");
  std::vector<std::string> log;
  kernel.spawn(a, "a", [&] {
    kernel.consume(microseconds(5));
    log.push_back(stamp("a", kernel.now()));
  });
  kernel.spawn(b, "b", [&] {
    kernel.consume(microseconds(2));
    log.push_back(stamp("b", kernel.now()));
    kernel.consume(microseconds(2));
    log.push_back(stamp("b", kernel.now()));
  });
  kernel.run();
  EXPECT_EQ(log, (std::vector<std::string>{"b@2.000000 us", "b@4.000000 us", "a@5.000000 us"}));
}

TEST(KernelProcess, BlockedProcessResumesWhenWoken) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  NamedTarget gate("gate");
  Tick resumed_at = -1;
  Process& waiter = kernel.spawn(
      cpu, "waiter",
      [&] {
        kernel.block(WaitInfo{WaitKind::other, &gate});
        resumed_at = kernel.now();
      });
  kernel.schedule_at(microseconds(7), event_priority::normal, [&] { kernel.wake(waiter); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(resumed_at, microseconds(7));
}

TEST(KernelProcess, BlockUntilReportsWhetherTheDeadlineWokeIt) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  std::vector<std::pair<bool, Tick>> outcomes;
  Process& p = kernel.spawn(
      cpu, "p",
      [&] {
        const bool first = kernel.block_until(microseconds(10), WaitInfo{WaitKind::timer, nullptr});
        outcomes.emplace_back(first, kernel.now());
        const bool second =
            kernel.block_until(microseconds(20), WaitInfo{WaitKind::timer, nullptr});
        outcomes.emplace_back(second, kernel.now());
      });
  kernel.schedule_at(microseconds(4), event_priority::normal, [&] { kernel.wake(p); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  ASSERT_EQ(outcomes.size(), 2U);
  EXPECT_EQ(outcomes[0], std::make_pair(false, microseconds(4)));
  EXPECT_EQ(outcomes[1], std::make_pair(true, microseconds(20)));
}

TEST(KernelProcess, DeadlockReportNamesEveryBlockedProcessAndWhatItWaitsOn) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node3");
  NamedTarget c("channel c");
  NamedTarget d("channel d");
  kernel.spawn(
      cpu, "producer",
      [&] {
        kernel.consume(microseconds(1));
        kernel.block(WaitInfo{WaitKind::channel_output, &c});
      });
  kernel.spawn(cpu, "consumer", [&] { kernel.block(WaitInfo{WaitKind::channel_input, &d}); });
  const RunResult result = kernel.run();
  ASSERT_EQ(result.reason, StopReason::deadlock);
  ASSERT_TRUE(result.deadlock.has_value());
  const DeadlockReport& report = *result.deadlock;
  EXPECT_EQ(report.time, microseconds(1));
  ASSERT_EQ(report.processes.size(), 2U);
  EXPECT_EQ(report.processes[0].process, "producer");
  EXPECT_EQ(report.processes[0].cpu, "node3");
  EXPECT_EQ(report.processes[0].kind, WaitKind::channel_output);
  EXPECT_EQ(report.processes[0].waiting_on, "channel c");
  EXPECT_EQ(report.processes[0].since, microseconds(1));
  EXPECT_EQ(report.processes[1].process, "consumer");
  EXPECT_EQ(report.processes[1].waiting_on, "channel d");
  EXPECT_EQ(report.processes[1].since, microseconds(1)); // it got the CPU when producer blocked
  EXPECT_EQ(report.text(),
            "deadlock at 1.000000 us: 2 processes blocked, no event pending\n"
            "  node3/producer (#1): channel output on channel c, since 1.000000 us\n"
            "  node3/consumer (#2): channel input on channel d, since 1.000000 us\n");
}

TEST(KernelProcess, KillingABlockedProcessRunsItsDestructors) {
  struct Flag {
    bool* set;
    ~Flag() { *set = true; }
  };
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  bool destroyed = false;
  bool reached_end = false;
  Process& p = kernel.spawn(cpu, "victim", [&] {
    Flag flag{&destroyed};
    kernel.block(WaitInfo{WaitKind::other, nullptr});
    reached_end = true;
  });
  kernel.run();
  EXPECT_EQ(kernel.live_processes(), 1U);
  kernel.kill(p);
  EXPECT_TRUE(destroyed);
  EXPECT_FALSE(reached_end);
  EXPECT_EQ(kernel.live_processes(), 0U);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
}

TEST(KernelProcess, KillingAProcessThatNeverRanSkipsItsBody) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  bool ran = false;
  Process& p = kernel.spawn(cpu, "never", [&] { ran = true; });
  kernel.kill(p);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_FALSE(ran);
}

TEST(KernelProcess, PowerOffKillsEveryProcessOfTheCpuIncludingOneMidCompute) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  Cpu& other = kernel.add_cpu("node1");
  int destroyed = 0;
  struct Count {
    int* n;
    ~Count() { ++*n; }
  };
  kernel.spawn(cpu, "waiting", [&] {
    Count c{&destroyed};
    kernel.block(WaitInfo{});
  });
  kernel.spawn(cpu, "computing", [&] {
    Count c{&destroyed};
    kernel.consume(milliseconds(5));
  });
  bool survivor_done = false;
  kernel.spawn(
      other, "survivor",
      [&] {
        kernel.consume(milliseconds(2));
        survivor_done = true;
      });
  kernel.schedule_at(milliseconds(1), event_priority::power, [&] { kernel.kill_all(cpu); });
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(destroyed, 2);
  EXPECT_TRUE(survivor_done);
  EXPECT_EQ(kernel.now(), milliseconds(2));
  EXPECT_EQ(cpu.busy_time(), milliseconds(1));
}

TEST(KernelProcess, DestroyingTheKernelUnwindsLiveProcesses) {
  bool destroyed = false;
  {
    struct Flag {
      bool* set;
      ~Flag() { *set = true; }
    };
    Kernel kernel;
    Cpu& cpu = kernel.add_cpu("node0");
    kernel.spawn(
        cpu, "forever",
        [&] {
          Flag flag{&destroyed};
          kernel.block(WaitInfo{});
        });
    kernel.spawn(cpu, "never started", [&] { Flag flag{&destroyed}; });
    kernel.run_until(0);
  }
  EXPECT_TRUE(destroyed);
}

TEST(KernelProcess, ExceptionInAProcessComesOutOfRun) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  kernel.spawn(cpu, "faulty", [&] {
    kernel.consume(microseconds(1));
    throw std::runtime_error("memory fault in faulty");
  });
  EXPECT_THROW(kernel.run(), std::runtime_error);
}

TEST(KernelProcess, HighPriorityPreemptsLowMidComputeAfterTheLatency) {
  Kernel kernel;
  CpuTiming timing;
  timing.preemption_latency = nanoseconds(600);
  Cpu& cpu = kernel.add_cpu("node0", timing);
  Tick low_end = -1;
  Tick high_start = -1;
  kernel.spawn(cpu, "low", [&] {
    kernel.consume(microseconds(10));
    low_end = kernel.now();
  });
  Process& high = kernel.spawn(
      cpu, "high",
      [&] {
        kernel.block(WaitInfo{});
        high_start = kernel.now();
        kernel.consume(microseconds(2));
      },
      SpawnOptions{Priority::high});
  kernel.schedule_at(microseconds(3), event_priority::normal, [&] { kernel.wake(high); });
  kernel.run();
  // The high process starts 600 ns after its event, runs 2 us; low resumes its last 7 us.
  EXPECT_EQ(high_start, microseconds(3) + nanoseconds(600));
  EXPECT_EQ(low_end, microseconds(3) + nanoseconds(600) + microseconds(2) + microseconds(7));
}

TEST(KernelProcess, LowPriorityIsDescheduledAfterTwoTimesliceTicks) {
  Kernel kernel;
  CpuTiming timing;
  timing.timeslice = microseconds(100);
  timing.slices_before_deschedule = 2;
  Cpu& cpu = kernel.add_cpu("node0", timing);
  std::vector<std::string> log;
  for (std::string name : {"a", "b"}) {
    kernel.spawn(
        cpu, name,
        [&, name] {
          for (int chunk = 0; chunk < 6; ++chunk) {
            kernel.consume(microseconds(60));
            log.push_back(fmt::format("{}{}", name, chunk));
          }
        });
  }
  kernel.run();
  // a runs chunks ending at 60, 120, 180, 240: at the boundary at 240 us it has seen the ticks
  // at 100 and 200 and gives way to b (which then runs 240..480 likewise).
  ASSERT_GE(log.size(), 5U);
  EXPECT_EQ(log[0], "a0");
  EXPECT_EQ(log[3], "a3");
  EXPECT_EQ(log[4], "b0");
  EXPECT_EQ(kernel.now(), microseconds(720));
}

TEST(KernelProcess, TenThousandProcessesCanLiveAtOnce) {
  Kernel kernel(KernelOptions{16 * 1024});
  Cpu& cpu = kernel.add_cpu("node0");
  int finished = 0;
  for (int i = 0; i < 10'000; ++i) {
    kernel.spawn(
        cpu, fmt::format("p{}", i),
        [&, i] {
          kernel.consume(nanoseconds(i % 7 + 1));
          ++finished;
        });
  }
  EXPECT_EQ(kernel.live_processes(), 10'000U);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(finished, 10'000);
}

} // namespace
} // namespace marsokhod::emulator
