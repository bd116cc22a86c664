// Mnemonics of the T805 instructions and the cycle count of an instruction mix.

#include "marsokhod/emulator/node/cost_table.hpp"

#include <algorithm>

namespace marsokhod::emulator {

namespace {

// The platform-file key of an enumerator of instruction_list.def: its name without the trailing
// underscore that steps around a keyword (and_ is "and").
constexpr std::string_view mnemonic_of(std::string_view enumerator) {
  if (enumerator.ends_with('_'))
    enumerator.remove_suffix(1);
  return enumerator;
}

// Indexed by enum class Instruction, generated from the same list.
constexpr std::array<std::string_view, kInstructionCount> kMnemonics = {
#define MARSOKHOD_INSTRUCTION(name) mnemonic_of(#name),
#include "marsokhod/emulator/node/instruction_list.def"
};

constexpr bool mnemonics_are_unique() {
  for (std::size_t i = 0; i < kMnemonics.size(); ++i) {
    for (std::size_t j = i + 1; j < kMnemonics.size(); ++j)
      if (kMnemonics[i] == kMnemonics[j])
        return false;
  }
  return true;
}
static_assert(mnemonics_are_unique(), "two instructions would share a platform-file key");

} // namespace

std::string_view mnemonic(Instruction instruction) {
  return kMnemonics[static_cast<std::size_t>(instruction)];
}

std::optional<Instruction> instruction_from_mnemonic(std::string_view name) {
  const auto found = std::find(kMnemonics.begin(), kMnemonics.end(), name);
  if (found == kMnemonics.end())
    return std::nullopt;
  return static_cast<Instruction>(found - kMnemonics.begin());
}

InstructionMix& InstructionMix::add(Instruction instruction, std::uint64_t times,
                                    std::uint64_t units_each) {
  const auto i = static_cast<std::size_t>(instruction);
  count[i] += times;
  units[i] += times * units_each;
  return *this;
}

InstructionMix& InstructionMix::operator+=(const InstructionMix& other) {
  for (std::size_t i = 0; i < kInstructionCount; ++i) {
    count[i] += other.count[i];
    units[i] += other.units[i];
  }
  external_accesses += other.external_accesses;
  return *this;
}

std::uint64_t CostTable::cycles(const InstructionMix& mix) const {
  std::uint64_t integer = 0;
  std::uint64_t fpu = 0;
  for (std::size_t i = 0; i < kInstructionCount; ++i) {
    if (mix.count[i] == 0)
      continue;
    const InstructionCost& cost = instructions[i];
    const std::uint64_t c = mix.count[i] * static_cast<std::uint64_t>(cost.base) +
                            mix.units[i] * static_cast<std::uint64_t>(cost.per_unit);
    (cost.fpu ? fpu : integer) += c;
  }
  const std::int64_t extra = std::max<std::int64_t>(0, external_access_cycles + wait_states - 1);
  integer += mix.external_accesses * static_cast<std::uint64_t>(extra);
  return std::max(integer, fpu);
}

} // namespace marsokhod::emulator
