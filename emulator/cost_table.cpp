#include "marsokhod/emulator/cost_table.hpp"

#include <algorithm>

namespace marsokhod::emulator {

namespace {

// Same order as enum class Instruction.
constexpr std::string_view kMnemonics[] = {
    "ldl",          "stl",         "ldlp",         "ldnl",
    "stnl",         "ldnlp",       "ldc",          "adc",
    "eqc",          "ajw",         "lb",           "sb",
    "bsub",         "wsub",        "add",          "sub",
    "diff",         "sum",         "gt",           "and",
    "or",           "xor",         "not",          "shl",
    "shr",          "mul",         "prod",         "div",
    "rem",          "j",           "cj_not_taken", "cj_taken",
    "call",         "ret",         "lend_loop",    "lend_exit",
    "pfix",         "nfix",        "move",         "startp",
    "endp",         "runp",        "stopp",        "in",
    "out",          "outbyte",     "outword",      "alt",
    "altwt_ready",  "altwt_wait",  "enbc_ready",   "enbc_not_ready",
    "disc",         "enbs",        "diss",         "altend",
    "ldtimer",      "tin_passed",  "tin_wait",     "talt",
    "taltwt_ready", "taltwt_wait", "enbt",         "dist",
    "fpadd",        "fpsub",       "fpmul",        "fpmul_db",
    "fpdiv",        "fpdiv_db",    "fpldnlsn",     "fpldnldb",
    "fpstnlsn",     "fpgt",        "fprtoi32",     "fpusqrtstep"};

static_assert(std::size(kMnemonics) == kInstructionCount, "one mnemonic per instruction");

} // namespace

std::string_view mnemonic(Instruction instruction) {
  return kMnemonics[static_cast<std::size_t>(instruction)];
}

std::optional<Instruction> instruction_from_mnemonic(std::string_view name) {
  const auto* found = std::find(std::begin(kMnemonics), std::end(kMnemonics), name);
  if (found == std::end(kMnemonics)) {
    return std::nullopt;
  }
  return static_cast<Instruction>(found - std::begin(kMnemonics));
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
    if (mix.count[i] == 0) {
      continue;
    }
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
