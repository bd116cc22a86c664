// The navigation program's processes: names, priorities, code and workspace sizes.
#pragma once

// The navigation program's processes as the program and its memory plan see them (private to
// the navigation room).

#include "marsokhod/emulator/kernel/process.hpp"

#include <cstddef>
#include <span>
#include <string_view>

namespace marsokhod::occam_port::detail {

/// One process of the program with the memory a period occam compiler would give it.
struct ProcessSpec {
  std::string_view name;
  emulator::Priority priority = emulator::Priority::low;
  /// Code bytes: [I] compiled occam runs 1.07-1.50 bytes per instruction (OCCAM_COSTS.md,
  /// "instruction stream density"); each process's static instruction count is estimated from
  /// the loops it nests, a few hundred instructions per kernel.
  std::size_t code_bytes = 0;
  /// Workspace: [X] `oc` gave PROC stereo of the probe kit 86 workspace words with its arrays in
  /// vector space; the program's processes, with a few more locals and call frames, get 128
  /// words (the motion scheme, a small state machine, 64).
  std::size_t workspace_bytes = 0;
};

/// Every process, in the order the program starts them.
std::span<const ProcessSpec> program_processes();

} // namespace marsokhod::occam_port::detail
