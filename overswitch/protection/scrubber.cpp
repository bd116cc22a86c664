// The scrubber process.

#include "marsokhod/overswitch/protection/scrubber.hpp"

#include <algorithm>

namespace marsokhod::overswitch {

std::uint64_t scrub_word_cycles(const emulator::Node& module) {
  emulator::InstructionMix mix;
  mix.add(emulator::Instruction::ldl, 4)
      .add(emulator::Instruction::wsub, 2)
      .add(emulator::Instruction::ldnl)
      .add(emulator::Instruction::stnl)
      .add(emulator::Instruction::lend_loop);
  mix.external_accesses = 2;
  return module.cycles_of(mix);
}

emulator::Process& start_scrubber(emulator::Node& module, emulator::Tick period, const bool& stop) {
  const std::size_t bytes = module.memory().config().external_bytes;
  const std::size_t slice_bytes = kScrubSliceWords * emulator::MemoryArena::kWordBytes;
  const std::size_t slices = std::max<std::size_t>(1, (bytes + slice_bytes - 1) / slice_bytes);
  const emulator::Tick spacing = period / static_cast<emulator::Tick>(slices);
  return module.spawn(
      "scrubber",
      [&module, &stop, bytes, slice_bytes, spacing] {
        emulator::Kernel& kernel = module.kernel();
        const std::uint64_t word_cycles = scrub_word_cycles(module);
        emulator::Tick next = kernel.now();
        for (std::size_t offset = 0; !stop; offset = (offset + slice_bytes) % bytes) {
          const std::size_t length = std::min(slice_bytes, bytes - offset);
          module.compute_cycles(word_cycles * (length / emulator::MemoryArena::kWordBytes));
          module.upsets().scrub(emulator::MemoryArena::kExternalBase +
                                    static_cast<emulator::Address>(offset),
                                length);
          next += spacing;
          if (next > kernel.now())
            kernel.block_until(next, emulator::WaitInfo{emulator::WaitKind::timer, nullptr});
        }
      },
      emulator::NodeSpawnOptions{emulator::Priority::low, 0, 0, nullptr});
}

} // namespace marsokhod::overswitch
