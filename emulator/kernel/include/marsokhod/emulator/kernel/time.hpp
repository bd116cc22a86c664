// Simulated time: integer picosecond ticks, their units and their formatting.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace marsokhod::emulator {

/// Simulated time in picoseconds. An integer so that every run orders events identically; a
/// 33.3 ns T805-30 cycle is 33'333 ps, and 2^63 ps is about 106 days of simulated time.
using Tick = std::int64_t;

inline constexpr Tick kPicosecond = 1;
inline constexpr Tick kNanosecond = 1'000;
inline constexpr Tick kMicrosecond = 1'000'000;
inline constexpr Tick kMillisecond = 1'000'000'000;
inline constexpr Tick kSecond = 1'000'000'000'000;
/// "No time": an event that never fires, a wait without deadline.
inline constexpr Tick kNever = std::numeric_limits<Tick>::max();

constexpr Tick nanoseconds(std::int64_t n) {
  return n * kNanosecond;
}
constexpr Tick microseconds(std::int64_t n) {
  return n * kMicrosecond;
}
constexpr Tick milliseconds(std::int64_t n) {
  return n * kMillisecond;
}

constexpr double to_microseconds(Tick t) {
  return static_cast<double>(t) / kMicrosecond;
}
constexpr double to_seconds(Tick t) {
  return static_cast<double>(t) / kSecond;
}

/// Readable time for reports, e.g. "12.345678 us"; exact to the picosecond.
std::string format_time(Tick t);

} // namespace marsokhod::emulator
