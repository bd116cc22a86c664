// Random ALT/PAR schedules checked against a reference model.
//
// Every message sent on a channel arrives exactly once and in order, every ALT takes a ready
// guard and no ready guard listed before it, and every schedule ends without deadlock.

#include "occam_port/occam_rig.hpp"

#include "marsokhod/occam_port/occam.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace marsokhod::occam_port {
namespace {

using emulator::Priority;
using emulator::StopReason;

/// Schedules to run: 10^5, fewer in sanitizer builds; MARSOKHOD_SCHEDULES overrides.
std::int64_t schedule_count() {
  if (const char* text = std::getenv("MARSOKHOD_SCHEDULES"))
    return std::strtoll(text, nullptr, 10);
#if defined(__SANITIZE_ADDRESS__)
  return 10'000;
#else
  return 100'000;
#endif
}

/// Raw generator output reduced by hand, so the schedules are the same on every library.
class Dice {
public:
  explicit Dice(std::uint64_t seed) : engine_(seed) {}
  std::uint64_t below(std::uint64_t n) { return engine_() % n; }
  bool chance(std::uint64_t percent) { return below(100) < percent; }

private:
  std::mt19937_64 engine_;
};

struct Sender {
  std::unique_ptr<Chan<int>> channel;
  std::vector<int> delays; // cycles of work before each message
};

struct Scenario {
  std::vector<Sender> senders;
  bool consumer_high = false;
  bool senders_high = false;
  bool skip_guard = false;
  bool timer_guard = false;
};

Scenario make_scenario(Dice& dice, std::int64_t index) {
  Scenario s;
  const auto count = 1 + dice.below(4);
  for (std::uint64_t i = 0; i < count; ++i) {
    Sender sender;
    sender.channel = std::make_unique<Chan<int>>(fmt::format("s{}.{}", index, i));
    const auto messages = dice.below(6);
    for (std::uint64_t m = 0; m < messages; ++m)
      sender.delays.push_back(static_cast<int>(dice.chance(50) ? 0 : dice.below(200)));
    s.senders.push_back(std::move(sender));
  }
  s.consumer_high = dice.chance(30);
  s.senders_high = dice.chance(30);
  s.skip_guard = dice.chance(30);
  s.timer_guard = dice.chance(30);
  return s;
}

/// What the checker found wrong; empty when the schedule behaved.
struct Findings {
  std::int64_t pri_violations = 0;
  std::int64_t unready_selections = 0;
  std::int64_t wrong_messages = 0;
};

void consume(Scenario& s, Dice& dice, Findings& findings, std::vector<std::vector<int>>& received) {
  Timer tim;
  std::size_t total = 0;
  for (const Sender& sender : s.senders)
    total += sender.delays.size();
  std::size_t got = 0;
  std::vector<Guard> guards;
  while (got < total) {
    guards.clear();
    const bool may_mask = s.skip_guard || s.timer_guard;
    for (std::size_t i = 0; i < s.senders.size(); ++i) {
      const bool open = received[i].size() < s.senders[i].delays.size();
      guards.push_back(when(open && !(may_mask && dice.chance(20)), input(*s.senders[i].channel)));
    }
    const std::int32_t deadline = tim.read() + static_cast<std::int32_t>(dice.below(3));
    if (s.timer_guard)
      guards.push_back(after(tim, deadline));
    if (s.skip_guard)
      guards.push_back(skip());
    const std::size_t k = pri_alt(guards);
    const std::int32_t clock = tim.read();
    auto ready = [&](const Guard& g) {
      if (!g.precondition)
        return false;
      switch (g.kind) {
      case Guard::Kind::channel:
        return g.channel->ready_for_input();
      case Guard::Kind::timer:
        // The clock was read 2 cycles after the ALT ended; allow that one tick.
        return is_after(clock, g.after);
      case Guard::Kind::skip:
        return true;
      }
      return false;
    };
    for (std::size_t j = 0; j < k; ++j)
      if (guards[j].kind != Guard::Kind::timer && ready(guards[j]))
        ++findings.pri_violations;
    if (!ready(guards[k]))
      ++findings.unready_selections;
    if (k >= s.senders.size()) {
      // Timeout or SKIP: pause for a tick or two. High priority is never timesliced, so a
      // high-priority consumer that polls without waiting would starve the senders (as on a
      // real transputer); tin itself takes about a tick, hence +2.
      tim.wait_after(tim.read() + 2);
      continue;
    }
    int value = -1;
    *s.senders[k].channel >> value;
    if (value != static_cast<int>(received[k].size()))
      ++findings.wrong_messages;
    received[k].push_back(value);
    ++got;
  }
}

void send(Sender& sender) {
  for (std::size_t m = 0; m < sender.delays.size(); ++m) {
    compute(emulator::Instruction::ldc, static_cast<std::uint64_t>(sender.delays[m]));
    *sender.channel << static_cast<int>(m);
  }
}

TEST(RandomSchedules, NoMessageIsLostOrDuplicatedAndAltsFollowPriority) {
  emulator::NodeSpec spec = testing::pc_card_node();
  spec.memory.external_bytes = 64 * 1024;
  emulator::Kernel kernel(emulator::KernelOptions{16 * 1024});
  emulator::Node node(kernel, spec);
  Dice dice(0x5eed'0ccaULL);
  Findings findings;
  const std::int64_t schedules = schedule_count();
  std::int64_t messages = 0;
  std::int64_t incomplete = 0;
  for (std::int64_t n = 0; n < schedules; ++n) {
    Scenario s = make_scenario(dice, n);
    std::vector<std::vector<int>> received(s.senders.size());
    node.spawn(
        "consumer", [&] { consume(s, dice, findings, received); },
        {s.consumer_high ? Priority::high : Priority::low});
    node.spawn("senders",
               [&] {
                 std::vector<std::function<void()>> branches;
                 for (Sender& sender : s.senders) {
                   branches.emplace_back([&sender] { send(sender); });
                 }
                 par(branches);
               },
               {s.senders_high ? Priority::high : Priority::low});
    const auto result = kernel.run();
    ASSERT_EQ(result.reason, StopReason::finished)
        << "schedule " << n << ": " << (result.deadlock ? result.deadlock->text() : "");
    for (std::size_t i = 0; i < s.senders.size(); ++i) {
      // Reference model: the channel delivers exactly the sequence 0, 1, ..., n-1.
      std::vector<int> expected(s.senders[i].delays.size());
      for (std::size_t m = 0; m < expected.size(); ++m)
        expected[m] = static_cast<int>(m);
      incomplete += received[i] == expected ? 0 : 1;
      messages += static_cast<std::int64_t>(received[i].size());
    }
  }
  EXPECT_EQ(incomplete, 0);
  EXPECT_EQ(findings.wrong_messages, 0);
  EXPECT_EQ(findings.pri_violations, 0);
  EXPECT_EQ(findings.unready_selections, 0);
  EXPECT_GT(messages, schedules); // the schedules did carry traffic
  RecordProperty("schedules", std::to_string(schedules));
  RecordProperty("messages", std::to_string(messages));
}

} // namespace
} // namespace marsokhod::occam_port
