// compute(): charges the current process for executing instructions.
#pragma once

#include "marsokhod/emulator/node/cost_table.hpp"

#include <cstdint>

namespace marsokhod::occam_port {

/// Charges the current process's CPU for executing `mix` (one compute chunk: a low-priority
/// process may be timesliced at its end).
void compute(const emulator::InstructionMix& mix);
/// Charges `times` executions of one instruction (`units_each`: words moved, bits shifted).
void compute(emulator::Instruction instruction, std::uint64_t times = 1,
             std::uint64_t units_each = 0);

} // namespace marsokhod::occam_port
