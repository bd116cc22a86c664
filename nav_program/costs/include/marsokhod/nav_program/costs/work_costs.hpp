// What the navigation's units of work cost as compiled occam on a T805: the instructions the
// INMOS occam 2 compiler emits for one unit of each nav::Work kind.
#pragma once

#include "marsokhod/emulator/node/cost_table.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <cstdint>
#include <span>
#include <string_view>

namespace marsokhod::nav_program {

/// What one unit of a nav::Work kind costs as compiled occam: its dynamic instruction mix and
/// its accesses to image and map buffers. The navigation kernels are written once, in C++, and
/// report their units (contract 1 of the design); this table is what the emulator charges for
/// them, so that an emulated node runs as long as the 1995 occam program would have.
struct WorkCost {
  nav::Work kind;
  /// Instructions one unit executes (InstructionMix::add(instruction, times, units_each));
  /// loop control of the enclosing replicated SEQ is included per unit. Prefix bytes are
  /// counted as pfix/nfix, one cycle each, as the data book charges them.
  emulator::InstructionMix per_unit;
  /// Word accesses one unit makes to the stage's buffers (images, feature maps, cost rows,
  /// maps): these go to external memory when the buffers were placed there; scalars and loop
  /// control live in the workspace, on chip.
  std::uint32_t buffer_accesses = 0;
  std::string_view occam; ///< the occam the entry stands for (a few lines, as a period
                          ///< programmer would write the unit)
  /// The instructions oc emits for that occam, one unit, in the order they run: the text the
  /// mix is counted from (a mnemonic per instruction, its operand where it needs prefix bytes
  /// or sets a time, `*` on each buffer access); docs/cost-table.md gives the notation.
  std::string_view code;
  std::string_view source; ///< where the figures come from (OCCAM_COSTS.md row, [X]/[I])
};

/// The timing model's one fitted constant: the cycles a unit of work took in the 1995
/// navigation's occam over the table's, whose listings are careful occam (row abbreviations,
/// running sums, range checks on). The kit's measurements bracket it: the same 3x3 window
/// costs 0.85 times as much with range checks off and 2.05 times with naive 2-D indexing
/// (docs/timing.md). Fitted on the paper's "stereo reconstruction of 128x128 in 8 s on one
/// transputer module" by `marsokhod reproduce`, which fits it again and reports both.
inline constexpr double kOccamStyleFactor = 1.266;

/// Every kind's entry, in nav::Work order (count_ has none).
std::span<const WorkCost> work_costs();

/// The entry of `kind`; std::invalid_argument for nav::Work::count_ or a value past it.
const WorkCost& work_cost(nav::Work kind);

/// The instructions `count` units execute, with their buffer accesses counted as external
/// accesses when `buffers_external`. std::overflow_error if a count would not fit 64 bits.
emulator::InstructionMix work_mix(nav::Work kind, std::uint64_t count, bool buffers_external);

} // namespace marsokhod::nav_program
