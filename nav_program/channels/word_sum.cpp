// The program's word sums and their cost.

#include "channels/word_sum.hpp"

#include <algorithm>
#include <cstring>

namespace marsokhod::nav_program::detail {

std::uint32_t word_sum(std::span<const std::byte> bytes) {
  std::uint32_t sum = 0;
  for (std::size_t i = 0; i < bytes.size(); i += 4) {
    std::uint32_t word = 0;
    std::memcpy(&word, bytes.data() + i, std::min<std::size_t>(4, bytes.size() - i));
    sum += word;
  }
  return sum;
}

void charge_word_sum(emulator::Node& node, std::size_t bytes) {
  const std::uint64_t words = (bytes + 3) / 4;
  emulator::InstructionMix mix;
  mix.add(emulator::Instruction::ldnl, words)
      .add(emulator::Instruction::sum, words)
      .add(emulator::Instruction::lend_loop, words);
  mix.external_accesses = words;
  node.compute(mix);
}

} // namespace marsokhod::nav_program::detail
