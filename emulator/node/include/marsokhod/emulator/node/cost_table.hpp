// The T805 cost model: its instructions, their data-book timings, and the processor part of a
// node description.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace marsokhod::emulator {

/// T805 instructions the cost model knows, one per entry of instruction_list.def. The platform
/// file's [cost_table] names them by mnemonic(); variants whose timing depends on an outcome get
/// a suffix (cj_taken).
enum class Instruction : std::uint8_t {
#define MARSOKHOD_INSTRUCTION(name) name,
#include "marsokhod/emulator/node/instruction_list.def"
  count
};

inline constexpr std::size_t kInstructionCount = static_cast<std::size_t>(Instruction::count);

/// Platform-file key of an instruction: "ldl", "and", "cj_taken", "in", "fpmul_db".
std::string_view mnemonic(Instruction instruction);
std::optional<Instruction> instruction_from_mnemonic(std::string_view name);

/// Cycles of one instruction: base + per_unit * units, with on-chip code and data.
struct InstructionCost {
  std::int32_t base = 0;
  std::int32_t per_unit = 0;
  /// Executed by the FPU, concurrently with integer instructions.
  bool fpu = false;
};

/// Dynamic instruction counts of a piece of work, plus how much of it touched external memory.
struct InstructionMix {
  std::array<std::uint64_t, kInstructionCount> count{};
  /// Sum of the units (words moved, bits shifted) over all executions of each instruction.
  std::array<std::uint64_t, kInstructionCount> units{};
  /// Word accesses (data and instruction fetches) that went to external memory.
  std::uint64_t external_accesses = 0;

  InstructionMix& add(Instruction instruction, std::uint64_t times = 1,
                      std::uint64_t units_each = 0);
  InstructionMix& operator+=(const InstructionMix& other);
};

/// Data-book timings of one processor type, filled from a platform file's [cost_table].
/// Every value carries its source in the platform file; nothing here is a default to trust.
struct CostTable {
  std::array<InstructionCost, kInstructionCount> instructions{};
  /// Processor cycles of one external-memory word access before wait states (T805: >= 3).
  std::int32_t external_access_cycles = 3;
  /// Extra cycles per external access (EMI wait states, configurable per board).
  std::int32_t wait_states = 0;
  /// Cycles from an event (link, timer, Event pin) to the high-priority process running:
  /// typical and worst case (T805: 19 and 58).
  std::int32_t event_latency_cycles = 19;
  std::int32_t event_latency_max_cycles = 58;

  const InstructionCost& operator[](Instruction i) const {
    return instructions[static_cast<std::size_t>(i)];
  }
  InstructionCost& operator[](Instruction i) { return instructions[static_cast<std::size_t>(i)]; }

  /// Cycles the mix takes: integer and FPU streams overlap (the longer one counts), each
  /// external access adds external_access_cycles + wait_states - 1 over the on-chip cycle.
  std::uint64_t cycles(const InstructionMix& mix) const;
};

/// The processor part of a node description (speed grade, scheduling, timers, costs).
struct CpuSpec {
  /// One processor cycle (T805-30: 33'333 ps, -25: 40'000 ps, -20: 50'000 ps).
  Tick cycle = 33'333;
  /// Low-priority timeslice (5120 periods of the 5 MHz input clock = 1.024 ms).
  Tick timeslice = 1'024 * kMicrosecond;
  /// Deschedule a low-priority process after this many timeslice ticks.
  std::int32_t slices_before_deschedule = 2;
  /// Timer tick periods: high priority 1 us, low priority 64 us.
  Tick high_timer_tick = kMicrosecond;
  Tick low_timer_tick = 64 * kMicrosecond;
  /// On-chip RAM in bytes (T805: 4096); accesses there take one cycle.
  std::size_t on_chip_bytes = 4096;
  CostTable costs;
};

} // namespace marsokhod::emulator
