// Where an upset or a stuck bit lands in a module's memory, and what it does there.
#pragma once

#include "marsokhod/emulator/memory/memory_upsets.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/overswitch/faults/fault.hpp"

#include <optional>
#include <string>

namespace marsokhod::overswitch {

/// What a memory fault struck, as its run reports it.
struct MemoryHit {
  emulator::Address address = 0; ///< the byte; the word's first byte for a check bit
  unsigned bit = 0;              ///< data bit 0..7, or check bit 0..6
  bool check_bit = false;
  bool on_chip = false;
  /// The block holding the byte; nothing when it was free, or reserved by the processor.
  std::optional<emulator::BlockInfo> block;
  bool reserved = false; ///< the bottom of on-chip RAM (link and event channel words)
  emulator::UpsetEffect effect = emulator::UpsetEffect::flipped;

  /// The bit reaches the program's data: an unprotected (or uncorrectable) hit on a data
  /// block.
  bool corrupts_data() const;
  /// The bit reaches what the processor runs on (code, a workspace, the reserved words): the
  /// module's behaviour is no longer the program's.
  bool corrupts_control() const;
  /// "external", "on-chip" or "on-chip reserved".
  std::string region() const;
  /// The block's label, or what the memory was ("free", "workspace of matching", "code").
  std::string buffer() const;
};

/// A memory fault's target could not be found on the module (no block matches the buffer, an
/// address outside its memory): what() says which.
class MemoryTargetError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Picks the bit the fault strikes, from `fault.memory` and the draw stream `fault.draw`, in
/// `module`'s memory as it is now, and applies it (an upset, or a stuck cell). Drawn bits are
/// uniform over the chosen memory's physical bits: 8 per byte, and 7 check bits per word the
/// EDAC covers. Throws MemoryTargetError.
MemoryHit strike_memory(emulator::Node& module, const Fault& fault);

/// Where strike_memory will strike, worked out before the run, for a fault whose bit does not
/// depend on what the memory holds (an address, or a draw over all memory): the same bit, its
/// block unknown; nothing for the other faults. `edac_external` as the module will have it.
std::optional<MemoryHit> locate_before_strike(const emulator::MemoryConfig& config,
                                              bool edac_external, const Fault& fault);

} // namespace marsokhod::overswitch
