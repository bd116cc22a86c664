// When each byte of the modules' memory held a block, over a fault-free run.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::overswitch {

/// The blocks each module held over a run, with when they were allocated and freed. A run with
/// faults is the fault-free run until its first fault strikes (the emulation is deterministic),
/// so the fault-free run's timeline tells whether a byte is free at a strike without emulating
/// up to it. A byte free at the strike is written before it is next read (every buffer is
/// written before it is read: the native program would otherwise read memory it never set), so
/// an upset there changes nothing: a campaign skips such runs (docs/faults.md, "Speed").
class MemoryTimeline {
public:
  /// Records `arena`'s blocks from now on, as `module`'s, timed by `kernel`. The arena and kernel
  /// must outlive the recording (it stops with stop()).
  void record(const std::string& module, emulator::MemoryArena& arena, emulator::Kernel& kernel);
  /// Stops recording (before the arenas go); blocks still held stay held for ever.
  void stop();

  /// What held a byte at an instant, if the timeline can tell.
  struct Holding {
    /// False when a block holding the byte was allocated or freed at that very instant: the order
    /// within one instant is not recorded (the run must then be emulated).
    bool sure = true;
    std::optional<emulator::BlockInfo> block; ///< nothing: free
  };
  Holding holding(const std::string& module, emulator::Address address, emulator::Tick time) const;

private:
  struct Span {
    emulator::BlockInfo block;
    emulator::Tick from = 0;
    emulator::Tick to = emulator::kNever;
  };
  std::map<std::string, std::vector<Span>> spans_;
  std::vector<emulator::MemoryArena*> recording_;
};

} // namespace marsokhod::overswitch
