// Simulated time: formatting ticks for people.

#include "marsokhod/emulator/kernel/time.hpp"

#include <fmt/format.h>

namespace marsokhod::emulator {

std::string format_time(Tick t) {
  if (t == kNever)
    return "never";
  const char* sign = t < 0 ? "-" : "";
  const Tick magnitude = t < 0 ? -t : t;
  return fmt::format("{}{}.{:06} us", sign, magnitude / kMicrosecond, magnitude % kMicrosecond);
}

} // namespace marsokhod::emulator
