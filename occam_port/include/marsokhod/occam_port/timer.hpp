// The occam TIMER and AFTER comparison on the wrapping transputer clock.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <cstdint>

namespace marsokhod::occam_port {

/// True when clock value `a` is AFTER `b` on the wrapping 32-bit transputer clock.
constexpr bool is_after(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) - static_cast<std::uint32_t>(b)) >
         0;
}

/// An occam TIMER: reads the clock of the current process's priority, which ticks every 1 us
/// (high) or 64 us (low) of simulated time on a T805.
class Timer {
public:
  /// `tim ? t` (ldtimer).
  std::int32_t read() const;
  /// `tim ? AFTER t` (tin): waits until the clock is after t, i.e. reads t+1.
  void wait_after(std::int32_t t) const;

  /// Clock value of a process of `period` at simulated time `now`.
  static std::int32_t clock_at(emulator::Tick now, emulator::Tick period);
  /// The first simulated time at which the clock is AFTER `t`, seen from `now`.
  static emulator::Tick time_after(std::int32_t t, emulator::Tick now, emulator::Tick period);
};

} // namespace marsokhod::occam_port
