// The occam TIMER: the wrapping clock of each priority, ldtimer and tin.

#include "marsokhod/occam_port/timer.hpp"

#include "marsokhod/emulator/node/node.hpp"

namespace marsokhod::occam_port {

using emulator::Instruction;
using emulator::Node;
using emulator::Tick;

std::int32_t Timer::clock_at(Tick now, Tick period) {
  // The clock register is 32 bits wide and wraps; keep the low 32 bits of the tick count.
  const auto ticks = static_cast<std::uint64_t>(now / period);
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(ticks & 0xffff'ffffU));
}

Tick Timer::time_after(std::int32_t t, Tick now, Tick period) {
  const std::int32_t clock = clock_at(now, period);
  if (is_after(clock, t))
    return now;
  const std::uint32_t distance = static_cast<std::uint32_t>(t) - static_cast<std::uint32_t>(clock);
  return (now / period + static_cast<Tick>(distance) + 1) * period;
}

std::int32_t Timer::read() const {
  Node& node = Node::current();
  node.execute(Instruction::ldtimer);
  const Tick period = node.timer_period(node.kernel().current()->priority());
  return clock_at(node.kernel().now(), period);
}

void Timer::wait_after(std::int32_t t) const {
  Node& node = Node::current();
  emulator::Kernel& kernel = node.kernel();
  const Tick period = node.timer_period(kernel.current()->priority());
  if (is_after(clock_at(kernel.now(), period), t)) {
    node.execute(Instruction::tin_passed);
    return;
  }
  node.execute(Instruction::tin_wait);
  const Tick wake_at = time_after(t, kernel.now(), period);
  if (wake_at > kernel.now())
    kernel.block_until(wake_at, emulator::WaitInfo{emulator::WaitKind::timer, nullptr});
}

} // namespace marsokhod::occam_port
