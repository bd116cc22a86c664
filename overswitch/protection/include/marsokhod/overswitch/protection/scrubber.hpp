// The EDAC scrubber: a low-priority process that rewrites a module's external memory.
#pragma once

#include "marsokhod/emulator/node/node.hpp"

namespace marsokhod::overswitch {

/// Words the scrubber rewrites in one go before it waits for its next slice.
inline constexpr std::size_t kScrubSliceWords = 1024;

/// The cycles of one word scrubbed, from `module`'s cost table: occam's
/// `w := mem[i]; mem[i] := w` in a replicated SEQ compiles to ldl x4, wsub x2, ldnl, stnl and
/// lend, with two external accesses (the read through the EDAC and the write back).
std::uint64_t scrub_word_cycles(const emulator::Node& module);

/// Starts the scrubber of `module`: at low priority, so that it takes the CPU only in turn with
/// the program, it rewrites the external memory slice by slice, spreading one whole pass over
/// `period`, and clears the single errors the EDAC held in each slice. It runs until its module
/// stops or, at a slice, finds `stop` set.
emulator::Process& start_scrubber(emulator::Node& module, emulator::Tick period, const bool& stop);

} // namespace marsokhod::overswitch
