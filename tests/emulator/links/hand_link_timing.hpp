// The link tests' hand-made timing, whose periods are worked out by hand in the tests.
#pragma once

#include "marsokhod/emulator/links/link_framing.hpp"

namespace marsokhod::emulator::link_testing {

/// 10 Mbit/s (100 ns per bit): 11-bit data packets of 1.1 us, 2-bit acks of 0.2 us sent 5.5
/// bits (0.55 us) after the start bit, the next byte 0.3 us after the ack, no gap: one way the
/// ack loop (1.05 us) is shorter than a packet, so packets go back to back.
inline LinkTiming hand_timing() {
  LinkTiming t;
  t.bit = 100'000;
  t.data_packet = 1'100'000;
  t.ack_packet = 200'000;
  t.ack_delay = 550'000;
  t.ack_turnaround = 300'000;
  t.gap = 0;
  return t;
}

/// One data packet (11 bits) at 10 Mbit/s.
inline constexpr Tick kByte = 1'100'000;
/// A byte's acknowledge ends this long after its start bit.
inline constexpr Tick kAckDone = 750'000;

} // namespace marsokhod::emulator::link_testing
