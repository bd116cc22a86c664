// Whole-node memory figures: bytes in use and high-water marks per region.
#pragma once

#include <cstddef>
#include <string>

namespace marsokhod::emulator {

/// Whole-node memory figures: bytes in use now and their high-water marks, per region.
struct ArenaUsage {
  std::size_t in_use_bytes = 0;
  std::size_t peak_bytes = 0;
  std::size_t on_chip_in_use_bytes = 0;
  std::size_t on_chip_peak_bytes = 0;
  std::size_t external_in_use_bytes = 0;
  std::size_t external_peak_bytes = 0;
  std::size_t workspace_bytes = 0;
  std::size_t allocations = 0;
  std::size_t frees = 0;
};

/// One owner's (process's) memory figures: data blocks and workspace kept apart.
struct OwnerUsage {
  std::string owner;
  std::size_t data_bytes = 0;
  std::size_t workspace_bytes = 0;
  std::size_t peak_bytes = 0;
  std::size_t allocations = 0;
  std::size_t frees = 0;
};

} // namespace marsokhod::emulator
