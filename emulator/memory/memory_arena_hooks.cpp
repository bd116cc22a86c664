// Connects a node's memory to the kernel: owner of each allocation, trace counters.

#include "marsokhod/emulator/memory/memory_arena_hooks.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace marsokhod::emulator {

void attach_memory(MemoryArena& arena, Kernel& kernel, const std::string& node) {
  arena.set_owner_provider([&kernel] {
    const Process* process = kernel.current();
    return process != nullptr ? process->name() : std::string("(no process)");
  });
  TraceSink* sink = kernel.trace();
  if (sink == nullptr)
    return;
  const TrackId track = sink->track(node, "memory");
  const auto sample = [&kernel, sink, track](const ArenaUsage& usage) {
    sink->counter(track, kernel.now(), "in_use_bytes",
                  static_cast<std::int64_t>(usage.in_use_bytes));
    sink->counter(track, kernel.now(), "high_water_bytes",
                  static_cast<std::int64_t>(usage.peak_bytes));
  };
  // The starting point, so that the counters show even for a node that never allocates.
  sample(arena.usage());
  arena.set_usage_listener(sample);
  arena.set_fault_listener([&kernel, sink, track](const MemoryFault& fault) {
    sink->instant(track, kernel.now(), "memory fault", fault.what());
  });
}

EventId schedule_bit_flip(Kernel& kernel, MemoryArena& arena, const std::string& node, Tick at,
                          Address address, unsigned bit) {
  if (!arena.contains(address) || bit > 7)
    throw std::out_of_range(fmt::format("{}: no bit {} at #{:08X} to flip", node, bit, address));
  return kernel.schedule_at(at, event_priority::normal, [&kernel, &arena, node, address, bit] {
    arena.flip_bit(address, bit);
    if (TraceSink* sink = kernel.trace())
      sink->instant(sink->track(node, "memory"), kernel.now(), "bit flip",
                    fmt::format("bit {} of #{:08X}", bit, address));
  });
}

} // namespace marsokhod::emulator
