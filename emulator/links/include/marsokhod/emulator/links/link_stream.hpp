// The link throughput experiment: byte streams between two nodes over one wire.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/emulator/trace/trace_sink.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace marsokhod::emulator {

/// A link throughput experiment: processes on two nodes stream bytes over the wire joining them.
struct LinkStreamOptions {
  /// Bytes sent in each direction that carries traffic.
  std::uint64_t bytes = 100'000;
  /// Both directions at once instead of one way.
  bool both_ways = false;
  /// Overrides the wire's speed (must be one of the processor's link speeds).
  std::optional<int> mbps;
  /// Size of each output/input message; the last one may be shorter.
  std::size_t message_bytes = 4096;
  /// Receives the run's trace records when set.
  TraceSink* trace = nullptr;
};

/// What the experiment measured, in emulated time.
struct LinkStreamResult {
  std::string from; ///< "module0.link0"
  std::string to;
  int mbps = 0;
  std::uint64_t bytes_moved = 0; ///< over all directions
  Tick elapsed = 0;              ///< until the last byte arrived
  double bytes_per_second = 0;   ///< bytes_moved / elapsed
  bool intact = false;           ///< every byte arrived, in order, unchanged
  std::uint64_t context_switches = 0;
};

/// Streams over the first wire of `platform` that joins two powered nodes. Each message costs
/// its process the data-book `out` or `in` base cycles on the node's CPU before the link
/// engine takes over. Throws std::invalid_argument when no such wire exists or for a speed
/// the processor does not offer.
LinkStreamResult run_link_stream(const PlatformSpec& platform, const LinkStreamOptions& options);

} // namespace marsokhod::emulator
