// compute(): charges the current process for a mix of instructions.

#include "marsokhod/occam_port/compute.hpp"

#include "marsokhod/emulator/node/node.hpp"

namespace marsokhod::occam_port {

void compute(const emulator::InstructionMix& mix) {
  emulator::Node::current().compute(mix);
}

void compute(emulator::Instruction instruction, std::uint64_t times, std::uint64_t units_each) {
  emulator::Node::current().execute(instruction, times, units_each);
}

} // namespace marsokhod::occam_port
