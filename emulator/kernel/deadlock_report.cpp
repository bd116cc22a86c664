// The text of a deadlock report: every process that can never run again.

#include "marsokhod/emulator/kernel/deadlock_report.hpp"

#include <fmt/format.h>

namespace marsokhod::emulator {

std::string DeadlockReport::text() const {
  std::string out =
      fmt::format("deadlock at {}: {} process{} blocked, no event pending\n", format_time(time),
                  processes.size(), processes.size() == 1 ? "" : "es");
  for (const BlockedProcess& p : processes) {
    out += fmt::format("  {}/{} (#{}): {} on {}, since {}\n", p.cpu, p.process, p.process_id,
                       to_string(p.kind), p.waiting_on, format_time(p.since));
  }
  return out;
}

} // namespace marsokhod::emulator
