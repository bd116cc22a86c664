// Reading a processor file: what the nodes of one processor type share.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"

#include <map>
#include <string>
#include <vector>

namespace marsokhod::emulator::detail {

/// What a processor file describes: everything common to the nodes of one processor type.
struct ProcessorSpec {
  std::string type;
  int links = 4;
  std::vector<int> link_speeds_mbps;
  /// Cycle time by speed grade ("T805-30" -> 33'333 ps).
  std::map<std::string, Tick, std::less<>> speed_grades;
  /// Everything but the cycle time and wait states, which depend on the node.
  CpuSpec cpu;
  std::size_t reserved_on_chip_bytes = 0;
  LinkTimingSpec link_timing;
};

/// Reads a processor file (see docs/formats.md, "Platform files").
ProcessorSpec load_processor(const std::string& file);

} // namespace marsokhod::emulator::detail
