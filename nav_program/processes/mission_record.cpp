// Encoding, checking and advancing the mission state.

#include "processes/mission_record.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <stdexcept>

namespace marsokhod::nav_program::detail {
namespace {

constexpr std::size_t kWords = kMissionRecordBytes / 4;

std::uint32_t real32(double value) {
  return std::bit_cast<std::uint32_t>(static_cast<float>(value));
}

double from_real32(std::uint32_t word) {
  return static_cast<double>(std::bit_cast<float>(word));
}

std::uint32_t check_of(const std::array<std::uint32_t, kWords>& words) {
  std::uint32_t check = 0x4D495353; // "MISS": an all-zero record is no valid one
  for (std::size_t i = 0; i + 1 < kWords; ++i)
    check ^= std::rotl(words[i], static_cast<int>(i));
  return check;
}

} // namespace

MissionRecord encode_mission(const MissionState& state) {
  std::array<std::uint32_t, kWords> words{};
  words[0] = static_cast<std::uint32_t>(state.motion.state);
  words[1] = real32(state.motion.turned_deg);
  words[2] = static_cast<std::uint32_t>(static_cast<std::int32_t>(state.motion.turn_sign));
  words[3] = real32(state.x_m);
  words[4] = real32(state.y_m);
  words[5] = real32(state.heading_deg);
  words[6] = state.uploads;
  words[7] = check_of(words);
  MissionRecord record;
  std::memcpy(record.data(), words.data(), record.size());
  return record;
}

MissionState decode_mission(std::span<const std::byte, kMissionRecordBytes> record) {
  std::array<std::uint32_t, kWords> words{};
  std::memcpy(words.data(), record.data(), record.size());
  if (words[7] != check_of(words))
    throw std::out_of_range("mission state: its check word does not match its record");
  if (words[0] > static_cast<std::uint32_t>(nav::MotionState::remote_control))
    throw std::out_of_range(fmt::format("mission state: {} is no motion state", words[0]));
  const auto sign = static_cast<std::int32_t>(words[2]);
  if (sign < -1 || sign > 1)
    throw std::out_of_range(fmt::format("mission state: {} is no turn sign", sign));
  MissionState state;
  state.motion.state = static_cast<nav::MotionState>(words[0]);
  state.motion.turned_deg = from_real32(words[1]);
  state.motion.turn_sign = static_cast<double>(sign);
  state.x_m = from_real32(words[3]);
  state.y_m = from_real32(words[4]);
  state.heading_deg = from_real32(words[5]);
  state.uploads = words[6];
  return state;
}

MissionState mission_after(const MissionState& before, const nav::MotionStatus& status,
                           std::span<const nav::DriveCommand> wheels) {
  MissionState after = before;
  after.motion = status;
  for (const nav::DriveCommand& command : wheels) {
    after.heading_deg += command.turn_deg;
    const double heading = after.heading_deg * std::numbers::pi / 180.0;
    after.x_m += command.distance_m * std::cos(heading);
    after.y_m += command.distance_m * std::sin(heading);
  }
  after.uploads += kUploadsPerCycle;
  return after;
}

} // namespace marsokhod::nav_program::detail
