// The cost table of nav work as compiled occam: counting each entry's code into an instruction
// mix, once, and scaling it by the units reported.

#include "marsokhod/nav_program/costs/work_costs.hpp"

#include "costs/work_listing.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace marsokhod::nav_program {
namespace {

using emulator::Instruction;

// The message is appended piece by piece: GCC 12 at -O3 warns (-Wrestrict, falsely) on chains
// of std::string operator+.
[[noreturn]] void fail(nav::Work kind, std::string_view what, std::string_view token = {}) {
  std::string message = "occam cost table, ";
  message.append(nav::to_string(kind)).append(": ");
  if (!token.empty())
    message.append("'").append(token).append("' ");
  message.append(what);
  throw std::logic_error(message);
}

bool is_one_of(Instruction instruction, std::initializer_list<Instruction> set) {
  return std::find(set.begin(), set.end(), instruction) != set.end();
}

// The instructions whose operand is encoded in their own byte and its prefixes.
bool is_function_code(Instruction i) {
  using enum Instruction;
  return is_one_of(
      i, {j, ldlp, ldnl, ldc, ldnlp, ldl, adc, call, cj_not_taken, cj_taken, ajw, eqc, stl, stnl});
}

// Operations whose time depends on units given in the listing (b, n or words).
bool takes_units(Instruction i) {
  using enum Instruction;
  return is_one_of(i, {prod, shl, shr, bitcnt, move, in, out});
}

// Operations with a code below 16 fit one `opr` byte; every other operation needs a pfix.
bool is_short_operation(Instruction i) {
  using enum Instruction;
  return is_one_of(
      i, {rev, lb, bsub, endp, diff, add, in, prod, gt, wsub, out, sub, startp, outbyte, outword});
}

// Operations reached through the FPU entry point: `ldc selector; fpentry` (fpentry is #AB).
bool is_fpu_entry(Instruction i) {
  using enum Instruction;
  return is_one_of(i, {fpuabs, fpusqrtfirst, fpusqrtstep, fpusqrtlast});
}

// The instructions that read or write memory, the only ones a '*' (a buffer access) may mark.
bool accesses_memory(Instruction i) {
  using enum Instruction;
  return is_one_of(
      i, {lb, sb, ldnl, stnl, fpldnlsn, fpldnldb, fpldnlsni, fpldnladdsn, fpldnlmulsn, fpstnlsn});
}

// Prefix bytes (pfix or nfix) in front of a function code with this operand: one per further
// nibble of a positive value; a negative value starts with nfix of the complement.
std::uint64_t prefix_bytes(std::int64_t operand) {
  if (operand < 0)
    return 1 + prefix_bytes(~operand >> 4);
  std::uint64_t prefixes = 0;
  for (; operand >= 16; operand >>= 4)
    ++prefixes;
  return prefixes;
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos)
    return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

// One instruction of a listing, `mnemonic[*] [operand]`, into the mix.
void count_instruction(nav::Work kind, std::string_view token, WorkCost& cost) {
  const auto space = token.find_first_of(" \t");
  std::string_view name = token.substr(0, space);
  const std::string_view operand_text =
      space == std::string_view::npos ? std::string_view{} : trimmed(token.substr(space));
  const bool buffer = name.ends_with('*');
  if (buffer)
    name.remove_suffix(1);
  const std::optional<Instruction> found = emulator::instruction_from_mnemonic(name);
  if (!found || *found == Instruction::pfix || *found == Instruction::nfix)
    fail(kind, "is not an instruction a listing may name", name);
  const Instruction instruction = *found;
  const bool wants_operand = is_function_code(instruction) || takes_units(instruction);
  std::int64_t operand = 0;
  if (wants_operand) {
    const auto [end, error] =
        std::from_chars(operand_text.data(), operand_text.data() + operand_text.size(), operand);
    if (operand_text.empty() || error != std::errc() ||
        end != operand_text.data() + operand_text.size())
      fail(kind, "needs one integer operand", token);
  } else if (!operand_text.empty()) {
    fail(kind, "takes no operand", token);
  }
  if (buffer && !accesses_memory(instruction))
    fail(kind, "does not access memory, so it cannot be a buffer access", token);
  emulator::InstructionMix& mix = cost.per_unit;
  if (is_function_code(instruction)) {
    mix.add(instruction);
    // A negative operand's prefixes end with one nfix; all the others are pfix.
    if (const std::uint64_t prefixes = prefix_bytes(operand); prefixes > 0) {
      mix.add(operand < 0 ? Instruction::nfix : Instruction::pfix);
      mix.add(Instruction::pfix, prefixes - 1);
    }
  } else {
    if (takes_units(instruction) && operand < 0)
      fail(kind, "has negative units", token);
    mix.add(instruction, 1, static_cast<std::uint64_t>(operand));
    if (is_fpu_entry(instruction))
      mix.add(Instruction::ldc); // the selector; its value is below 16
    if (!is_short_operation(instruction))
      mix.add(Instruction::pfix);
  }
  if (buffer)
    ++cost.buffer_accesses;
}

// A listing's code: instructions separated by ';' or line ends, `--` comments to the line end.
WorkCost count_listing(const detail::WorkListing& listing) {
  WorkCost cost{listing.kind, {}, 0, listing.occam, listing.code, listing.source};
  std::string_view rest = listing.code;
  while (!rest.empty()) {
    const auto line_end = rest.find('\n');
    std::string_view line = rest.substr(0, line_end);
    rest = line_end == std::string_view::npos ? std::string_view{} : rest.substr(line_end + 1);
    line = line.substr(0, line.find("--"));
    while (!line.empty()) {
      const auto separator = line.find(';');
      const std::string_view token = trimmed(line.substr(0, separator));
      line = separator == std::string_view::npos ? std::string_view{} : line.substr(separator + 1);
      if (!token.empty())
        count_instruction(listing.kind, token, cost);
    }
  }
  return cost;
}

using Table = std::array<WorkCost, nav::kWorkKinds>;

// Built on first use from the stage files' listings, each kind exactly once.
const Table& table() {
  static const Table built = [] {
    Table costs{};
    std::array<bool, nav::kWorkKinds> seen{};
    for (const auto listings :
         {detail::matching_listings(), detail::stereo_listings(), detail::map_listings()})
      for (const detail::WorkListing& listing : listings) {
        const auto at = static_cast<std::size_t>(listing.kind);
        if (at >= nav::kWorkKinds || seen[at])
          fail(listing.kind, "listed twice, or not a kind of work");
        seen[at] = true;
        costs[at] = count_listing(listing);
      }
    for (std::size_t at = 0; at < nav::kWorkKinds; ++at)
      if (!seen[at])
        fail(static_cast<nav::Work>(at), "has no listing");
    return costs;
  }();
  return built;
}

std::uint64_t times(std::uint64_t per_unit, std::uint64_t count) {
  if (per_unit != 0 && count > std::numeric_limits<std::uint64_t>::max() / per_unit)
    throw std::overflow_error(std::string("work_mix: ")
                                  .append(std::to_string(count))
                                  .append(" units overflow an instruction count"));
  return per_unit * count;
}

} // namespace

std::span<const WorkCost> work_costs() {
  return table();
}

const WorkCost& work_cost(nav::Work kind) {
  const auto at = static_cast<std::size_t>(kind);
  if (at >= nav::kWorkKinds)
    throw std::invalid_argument(
        std::string("work_cost: ").append(std::to_string(at)).append(" is not a kind of work"));
  return table()[at];
}

emulator::InstructionMix work_mix(nav::Work kind, std::uint64_t count, bool buffers_external) {
  const WorkCost& cost = work_cost(kind);
  emulator::InstructionMix mix;
  for (std::size_t i = 0; i < emulator::kInstructionCount; ++i) {
    mix.count[i] = times(cost.per_unit.count[i], count);
    mix.units[i] = times(cost.per_unit.units[i], count);
  }
  if (buffers_external)
    mix.external_accesses = times(cost.buffer_accesses, count);
  return mix;
}

} // namespace marsokhod::nav_program
