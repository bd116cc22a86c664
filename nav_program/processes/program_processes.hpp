// The navigation program's processes: names, priorities, code and workspace sizes, bodies,
// planned buffers and stage groups, made from process_list.def.
#pragma once

// The processes as the program, its run and its memory plan see them (private to the layer).

#include "processes/planned_buffers.hpp"

#include "marsokhod/emulator/kernel/process.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace marsokhod::nav_program::detail {

class ProcessContext;

/// One process of the program with the memory a period occam compiler would give it.
struct ProcessSpec {
  std::string_view name;
  emulator::Priority priority = emulator::Priority::low;
  std::size_t code_bytes = 0;
  std::size_t workspace_bytes = 0;
  StageGroup group = StageGroup::stereo;
  void (*body)(ProcessContext&) = nullptr;
  /// The buffers it holds at its peak, for the memory plan.
  std::vector<PlannedBuffer> (*buffers)(const BufferGeometry&, bool terrain_kept) = nullptr;
};

/// Every process, in the order the program starts them (process_list.def).
std::span<const ProcessSpec> program_processes();

/// The process named `name`; std::logic_error when the program has none.
const ProcessSpec& program_process(std::string_view name);

} // namespace marsokhod::nav_program::detail
