// What a deadlock leaves behind: every process that can never run again, and where.
#pragma once

#include "marsokhod/emulator/kernel/process.hpp"
#include "marsokhod/emulator/kernel/time.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::emulator {

/// One process that can never run again.
struct BlockedProcess {
  std::string cpu;     ///< node / CPU name
  std::string process; ///< process name
  std::uint64_t process_id = 0;
  WaitKind kind = WaitKind::none;
  std::string waiting_on; ///< the WaitTarget's description ("channel c", "ALT {...}")
  Tick since = 0;         ///< when it blocked
};

/// Why a simulation STOPped: every live process is blocked and no event is pending.
/// Processes are listed by CPU creation order, then process creation order.
struct DeadlockReport {
  Tick time = 0;
  std::vector<BlockedProcess> processes;

  /// Multi-line text for people, e.g.
  /// "deadlock at 3.000000 us: 2 processes blocked, no event pending\n"
  /// "  node0/consumer (#4): channel input on channel c, since 1.500000 us\n".
  std::string text() const;
};

} // namespace marsokhod::emulator
