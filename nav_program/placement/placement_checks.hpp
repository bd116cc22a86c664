// The checks of a placement that need the whole file: every process placed, every channel and
// device use with a wire.
#pragma once

#include "marsokhod/nav_program/placement/placement.hpp"

namespace marsokhod::nav_program::detail {

/// Throws std::invalid_argument when the shape lists a process twice, or a channel or device
/// use names a process the shape does not list: the program is wrong, not the file.
void check_shape(const ProgramShape& shape);

/// Checks a placement whose every entry was read and checked alone: each process of the shape
/// placed (else an error at `header_line`, the [placement] table's), a direct unbroken wire
/// between the nodes of every channel's two ends when they differ, and an unbroken wire from
/// the node of every device use to a powered frame store or host. Throws PlacementError.
void check_program_fits(const Placement& placement, int header_line,
                        const emulator::PlatformSpec& platform, const ProgramShape& shape);

/// An unbroken wire from `node` to a powered device that serves the program: a frame store
/// (images) or a host (images and telemetry on the PC card); nullptr if there is none.
const emulator::WireSpec* device_wire(const emulator::PlatformSpec& platform,
                                      const std::string& node);

} // namespace marsokhod::nav_program::detail
