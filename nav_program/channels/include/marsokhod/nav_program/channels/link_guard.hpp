// How the navigation program guards its messages on links, and what it reports of them.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <cstdint>
#include <optional>

namespace marsokhod::nav_program {

/// How the program guards its messages on links between modules (docs/faults.md, "Link
/// faults"). With a timeout, a sender whose message is not acknowledged in time gives it up and
/// resets its link (occam's OutputOrFail.t, which does the T805's resetch): a dead wire either
/// way, or a lost acknowledge, stalls the sender, since acknowledges come back on the wire
/// beside the data. With checksums, each message is followed by a 32-bit sum of its words that
/// the receiver checks. Either trouble is reported to the overswitch over the module's device
/// link, and the process stops.
struct LinkGuard {
  std::optional<emulator::Tick> output_timeout;
  bool checksums = false;
};

/// What a process reports of a link.
enum class LinkTrouble : std::uint8_t {
  timeout = 1,  ///< its output was not acknowledged in time
  checksum = 2, ///< a message came with a wrong checksum
};
const char* to_string(LinkTrouble trouble);

} // namespace marsokhod::nav_program
