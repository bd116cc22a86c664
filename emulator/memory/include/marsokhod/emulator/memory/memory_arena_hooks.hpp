// Connects a node's memory to the kernel: owner of each allocation, trace counters.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"

#include <string>

namespace marsokhod::emulator {

/// Connects a node's memory to the simulation: allocations through the std::pmr interface are
/// charged to the kernel's current process, and when the kernel has a trace sink, the node's
/// "memory" track gets counters (bytes in use, high-water mark) and an instant per fault.
/// The arena and kernel must outlive the simulation run.
void attach_memory(MemoryArena& arena, Kernel& kernel, const std::string& node);

/// Inverts bit `bit` of the byte at `address` at simulated time `at` (a particle hit) and
/// marks it on the node's memory track. An address outside populated memory is refused now.
EventId schedule_bit_flip(Kernel& kernel, MemoryArena& arena, const std::string& node, Tick at,
                          Address address, unsigned bit);

} // namespace marsokhod::emulator
