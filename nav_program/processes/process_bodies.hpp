// The bodies of the navigation program's processes and the messages they share.
#pragma once

// The processes' bodies and what they share (private to the layer).

#include "channels/cycle_messages.hpp"
#include "processes/cycle_state.hpp"

#include "marsokhod/nav_program/placement/memory_plan.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace marsokhod::nav_program::detail {

using U8Image = imaging::Image<std::uint8_t>;
using FloatImage = imaging::Image<float>;

inline std::string image_what(std::string_view what, int width, int height, int bytes) {
  return buffer_name(what, height, width, bytes);
}

inline U8Image receive_bytes(ProcessContext& c, BlockChannel& channel, std::string_view what,
                             int width, int height) {
  c.doing(image_what(what, width, height, 1));
  return receive_image<std::uint8_t>(channel, width, height, c.memory());
}

inline FloatImage receive_floats(ProcessContext& c, BlockChannel& channel, std::string_view what) {
  const CycleState& s = c.cycle();
  c.doing(image_what(what, s.width, s.height, 4));
  return receive_image<float>(channel, s.width, s.height, c.memory());
}

// A hand-over between two stages ends with a word the sender outputs once it has let go of what
// it handed on. The second process to reach a channel is the one that goes on (the first is
// only rescheduled), so without it a receiver could take its working buffers while the sender
// still held its own: the memory plan's hand-over counts the two stages' handed and received
// buffers, nothing more.
inline constexpr std::int32_t kHandOverClosed = 0x484f4646; // "HOFF"

inline void close_hand_over(BlockChannel& channel) {
  send_value(channel, kHandOverClosed);
}

/// std::logic_error if the two ends disagree on the protocol.
void await_hand_over(BlockChannel& channel);

// The body of each process (process_list.def): features, matching and refine in
// stereo_processes.cpp, the others in navigation_processes.cpp.
#define MARSOKHOD_PROCESS(name, priority, code, workspace, group) void name(ProcessContext& c);
#include "processes/process_list.def"

} // namespace marsokhod::nav_program::detail
