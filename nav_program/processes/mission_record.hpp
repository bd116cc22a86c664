// The mission state as an occam record in a module's memory (private to the layer).
#pragma once

#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <array>
#include <cstddef>
#include <span>

namespace marsokhod::nav_program::detail {

using MissionRecord = std::array<std::byte, kMissionRecordBytes>;

MissionRecord encode_mission(const MissionState& state);

/// Reads a record back; a record whose check word does not match, or whose motion state or
/// turn sign is no value the program writes, is refused with std::out_of_range (occam's range
/// check on a CASE without ELSE): a copy struck by an upset is never driven on.
MissionState decode_mission(std::span<const std::byte, kMissionRecordBytes> record);

/// The state the cycle leaves when the motion scheme took `step` with `wheels`: the new status,
/// the pose moved by the wheel commands (turn on the spot, then straight on), and the cycle's
/// uploads counted.
MissionState mission_after(const MissionState& before, const nav::MotionStatus& status,
                           std::span<const nav::DriveCommand> wheels);

/// Uploads telemetry sends each cycle: plan header, path pixels, drive commands, the motion
/// state and the wheel commands.
inline constexpr std::uint32_t kUploadsPerCycle = 5;

} // namespace marsokhod::nav_program::detail
