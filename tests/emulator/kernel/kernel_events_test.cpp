// Kernel events: their order, tags, cancellation, run limits and stops; time formatting.

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace marsokhod::emulator {
namespace {

TEST(KernelEvents, RunInTimeThenPriorityThenSchedulingOrder) {
  Kernel kernel;
  std::vector<std::string> order;
  auto record = [&](std::string name) { return [&order, name] { order.push_back(name); }; };
  kernel.schedule_at(20, event_priority::normal, record("t20"));
  kernel.schedule_at(10, event_priority::normal, record("t10 normal first"));
  kernel.schedule_at(10, event_priority::normal, record("t10 normal second"));
  kernel.schedule_at(10, event_priority::link, record("t10 link"));
  kernel.schedule_at(10, event_priority::power, record("t10 power"));
  const RunResult result = kernel.run();
  EXPECT_EQ(result.reason, StopReason::finished);
  EXPECT_EQ(result.time, 20);
  EXPECT_EQ(order, (std::vector<std::string>{"t10 power", "t10 link", "t10 normal first",
                                             "t10 normal second", "t20"}));
}

TEST(KernelEvents, CancelledEventNeverRuns) {
  Kernel kernel;
  int fired = 0;
  const EventId id = kernel.schedule_at(5, event_priority::normal, [&] { ++fired; });
  EXPECT_TRUE(kernel.cancel(id));
  EXPECT_FALSE(kernel.cancel(id));
  EXPECT_EQ(kernel.pending_events(), 0U);
  kernel.run();
  EXPECT_EQ(fired, 0);
}

TEST(KernelEvents, HandlerReceivesItsTag) {
  struct Collect : EventHandler {
    std::vector<std::uint64_t> tags;
    void on_event(std::uint64_t tag) override { tags.push_back(tag); }
  } collect;
  Kernel kernel;
  kernel.schedule_at(3, event_priority::normal, collect, 7);
  kernel.schedule_after(1, event_priority::normal, collect, 9);
  kernel.run();
  EXPECT_EQ(collect.tags, (std::vector<std::uint64_t>{9, 7}));
}

TEST(KernelEvents, RunUntilStopsAtTheLimitAndResumesLater) {
  Kernel kernel;
  std::vector<Tick> seen;
  for (Tick t : {100, 200, 300}) {
    kernel.schedule_at(
        t, event_priority::normal, [&seen, &kernel] { seen.push_back(kernel.now()); });
  }
  RunResult first = kernel.run_until(200);
  EXPECT_EQ(first.reason, StopReason::time_limit);
  EXPECT_EQ(first.time, 200);
  EXPECT_EQ(seen, (std::vector<Tick>{100, 200}));
  RunResult second = kernel.run_for(50);
  EXPECT_EQ(second.time, 250);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(seen, (std::vector<Tick>{100, 200, 300}));
}

TEST(KernelEvents, BackgroundEventsDoNotKeepTheRunAlive) {
  Kernel kernel;
  int samples = 0;
  std::function<void()> sample = [&] {
    ++samples;
    kernel.schedule_after(10, event_priority::sample, sample, EventKind::background);
  };
  kernel.schedule_at(0, event_priority::sample, sample, EventKind::background);
  kernel.schedule_at(35, event_priority::normal, [] {});
  const RunResult result = kernel.run();
  EXPECT_EQ(result.reason, StopReason::finished);
  EXPECT_EQ(result.time, 35);
  EXPECT_EQ(samples, 4); // at 0, 10, 20, 30
}

TEST(KernelEvents, StopReturnsAfterTheCurrentEvent) {
  Kernel kernel;
  int fired = 0;
  kernel.schedule_at(
      1, event_priority::normal,
      [&] {
        ++fired;
        kernel.stop();
      });
  kernel.schedule_at(2, event_priority::normal, [&] { ++fired; });
  EXPECT_EQ(kernel.run().reason, StopReason::stopped);
  EXPECT_EQ(fired, 1);
  EXPECT_EQ(kernel.run().reason, StopReason::finished);
  EXPECT_EQ(fired, 2);
}

TEST(Time, FormatsExactlyInMicroseconds) {
  EXPECT_EQ(format_time(12'345'678), "12.345678 us");
  EXPECT_EQ(format_time(-1), "-0.000001 us");
  EXPECT_EQ(format_time(kNever), "never");
}

} // namespace
} // namespace marsokhod::emulator
