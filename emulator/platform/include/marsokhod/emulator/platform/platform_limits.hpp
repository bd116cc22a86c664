// The range of every number in a platform or processor file, with the reason for each bound.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>

/// Bounds the platform and processor readers hold every value to (docs/formats.md, "Platform
/// files", "Ranges"). Each is a physical range of the T805 (T805.md) widened for what-if
/// platforms, or the largest value the emulator's integer picosecond arithmetic takes without
/// overflow, whichever is smaller. A value outside its range is refused with the range; none is
/// ever narrowed or wrapped into it.
namespace marsokhod::emulator::platform_limits {

// --- processor file: [processor] -------------------------------------------------------------

/// A T805 has four links, and a node models exactly those four (Node::kLinks).
inline constexpr int kMaxLinks = 4;
/// Entries of link_speeds_mbps. The T805 offers 5, 10 and 20 Mbit/s; up to 1000 Mbit/s the bit
/// time (10^12 / (mbps * 10^6) ps) is at least 1000 ps, so its integer rounding stays under
/// 0.1 %.
inline constexpr int kMinLinkMbps = 1;
inline constexpr int kMaxLinkMbps = 1000;
/// On-chip RAM ends where external memory starts, #80001000: at most 4096 bytes.
inline constexpr std::size_t kMaxOnChipBytes = 4096;
/// One external word access: the EMI runs six T-states of one to four half-cycles each, 3 to 12
/// processor cycles before wait states (T805.md, "Clock and memory").
inline constexpr std::int32_t kMinExternalAccessCycles = 3;
inline constexpr std::int32_t kMaxExternalAccessCycles = 12;
/// Low-priority timeslice. The T805's is fixed at 1.024 ms (5120 periods of its 5 MHz input
/// clock); a slice shorter than a microsecond would be shorter than a context switch, one
/// longer than a second is no timeslicing at all.
inline constexpr std::int64_t kMinTimesliceNs = 1'000;
inline constexpr std::int64_t kMaxTimesliceNs = 1'000'000'000;
/// Timeslices before a low-priority process is descheduled (T805: 2).
inline constexpr std::int32_t kMaxSlicesBeforeDeschedule = 1'000;
/// Timer tick periods (T805: 1 us high, 64 us low). An occam timer wait may lie 2^32 ticks
/// ahead; at 1 ms a tick that is 4.3e18 ps, under half the int64 range (checks below). A longer
/// tick could overflow the wake-up time.
inline constexpr std::int64_t kMinTimerTickNs = 1;
inline constexpr std::int64_t kMaxTimerTickNs = 1'000'000;

// --- processor file: [speed_grades], [cost_table], event latency ------------------------------

/// Processor cycle time in picoseconds: 1 GHz to 1 MHz. The T805 grades run at 20 to 30 MHz
/// (50'000 to 33'333 ps); the range leaves what-if grades a factor of 30 either way and keeps
/// a cycle count times the cycle time exact in int64 picoseconds for up to 9.2e12 cycles.
inline constexpr Tick kMinCyclePs = 1'000;
inline constexpr Tick kMaxCyclePs = 1'000'000;
/// Cycles of one cost-table entry (base and per_unit) and of the event latency. The slowest
/// data-book entry is 48 cycles (taltwt, waiting), the worst event latency 78 (with FPU
/// state); 1000 leaves room for what-ifs while one instruction stays under 10^9 ps.
inline constexpr std::int32_t kMaxInstructionCycles = 1'000;

// --- processor file: [link_timing] ------------------------------------------------------------

/// Packet lengths and handshake delays in bit times: an 11-bit data packet, a 2-bit ack and
/// delays of a few bit times on the T805; 1000 bit times is 1 ms at 1 Mbit/s.
inline constexpr double kMaxLinkBits = 1'000;
/// The speed-independent part of the ack turnaround (T805 fit: 100'000 ps): at most 10 us.
inline constexpr Tick kMaxAckTurnaroundPs = 10'000'000;

// --- platform file ----------------------------------------------------------------------------

/// External RAM per node in KB: the T805 address space above #80001000 (T805.md). The node's
/// memory is mapped lazily, so only the bytes a program touches take host memory.
inline constexpr std::int64_t kMaxExternalKb = 0x7FFFF000LL / 1024;
/// EMI wait states per external access (MemWait inserts whole cycles); the 3-cycle memories of
/// the period need none.
inline constexpr std::int32_t kMaxWaitStates = 64;
/// Nodes and devices of one platform. Every per-node step (wiring, attaching links, a trace
/// track each) stays small; the largest T805 machines had about a thousand processors.
inline constexpr std::size_t kMaxNodes = 1'024;
/// Overswitch timings, microseconds: from 1 us to an hour.
inline constexpr std::int64_t kMinOverswitchUs = 1;
inline constexpr std::int64_t kMaxOverswitchUs = 3'600'000'000;
inline constexpr std::size_t kMaxDevices = 1'024;
/// Links of a device: the IMS C004 link switch, the widest INMOS link device, has 32.
inline constexpr int kMaxDeviceLinks = 32;
/// A frame store's camera is chosen by a one-byte request: cameras 0 to 255.
inline constexpr int kMaxCameras = 256;
/// Image side in pixels: PAL video frames are 768 x 576, the paper's stereo 128 x 128; 2048
/// bounds one 16-bit image at 8 MiB.
inline constexpr int kMaxImageSide = 2'048;
/// Node and device names: letters, digits, '_' and '-', at most this many characters.
inline constexpr std::size_t kMaxNameLength = 64;

// --- what the bounds guarantee -----------------------------------------------------------------
// Every conversion of a file value to ticks, and the products the kernel forms from them, stays
// below half of int64 (so that adding the current time, up to another 2^62 ps = 53 days, cannot
// overflow either).
inline constexpr Tick kHalfTime = std::numeric_limits<Tick>::max() / 2;
// The end of the last slice before a deschedule: next tick + (slices - 1) * timeslice.
static_assert(kMaxTimesliceNs * kNanosecond * kMaxSlicesBeforeDeschedule < kHalfTime);
// An occam timer wake-up: (now / period + distance + 1) * period, distance < 2^32.
static_assert(((Tick{1} << 32) + 1) * kMaxTimerTickNs * kNanosecond < kHalfTime);
// One instruction, an event latency, an external access with every wait state.
static_assert(kMaxCyclePs * kMaxInstructionCycles < kHalfTime);
static_assert(kMaxCyclePs * (kMaxExternalAccessCycles + kMaxWaitStates) < kHalfTime);
// A link packet or delay at the slowest speed, plus the fixed turnaround.
static_assert(static_cast<Tick>(kMaxLinkBits) * (kSecond / (kMinLinkMbps * Tick{1'000'000})) +
                  kMaxAckTurnaroundPs <
              kHalfTime);
// External memory fits the host's size_t and the T805's 32-bit addresses.
static_assert(kMaxExternalKb * 1024 + 0x1000 <= std::int64_t{1} << 31);

} // namespace marsokhod::emulator::platform_limits
