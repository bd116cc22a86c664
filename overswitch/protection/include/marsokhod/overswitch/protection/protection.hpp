// What protects the onboard computer against its faults, and what each protection costs.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <optional>

namespace marsokhod::overswitch {

/// The protections a run or a campaign switches on (docs/faults.md, "Protection").
struct Protection {
  /// SEC-DED EDAC between each module and its external memory: single errors corrected on
  /// every read, double errors flagged (the module halts).
  bool edac = false;
  /// With EDAC: a scrubber on each module reads its external memory through the EDAC and writes
  /// it back, one whole pass per period, so that a single error is gone before a second can
  /// join it in the same word.
  std::optional<emulator::Tick> scrub_period;
  /// A checksum after each message on a link, checked by the receiver; a bad one is reported to
  /// the overswitch, which restarts the cycle on the pair (the retry is the whole cycle's).
  bool link_checksums = false;
  /// A check of the navigation's own: range sends a word sum of each row of the terrain with
  /// it, and zones and path check a row's sum each time they rebuild it; one that no longer
  /// checks stops the program with a run-time error (the module halts and fails over), so a
  /// terrain struck while kept is never planned on.
  bool terrain_check = false;
};

/// Something is switched on.
bool any(const Protection& protection);

/// Wait states the EDAC adds to every external access of a module: a flow-through SEC-DED unit
/// sits in the data path, and the IDT49C460A (IDT data sheet DSC-9017, August 1995) takes at
/// most 36 ns from data in to corrected data out, more than one 33.3 ns cycle of a T805-30:
/// two whole cycles. The check-bit generation on writes (30 ns) fits in the same two.
inline constexpr int kEdacWaitStates = 2;

/// The platform with the protection's hardware costs: EDAC adds kEdacWaitStates to the external
/// accesses of every module under the overswitch. Platforms without an [overswitch] table come
/// back unchanged.
emulator::PlatformSpec protected_platform(const emulator::PlatformSpec& platform,
                                          const Protection& protection);

} // namespace marsokhod::overswitch
