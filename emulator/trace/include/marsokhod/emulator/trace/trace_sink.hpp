// The receiver of trace records: tracks, slices, counters, instants and flows.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <cstdint>
#include <string_view>

namespace marsokhod::emulator {

/// One row in a trace viewer: a node CPU, a link direction, a memory counter.
using TrackId = std::uint32_t;

/// Receiver of trace records; the kernel, CPUs, links and memory arenas emit into it.
/// Implementations (the Chrome Trace Event JSON writer) must produce output that depends
/// only on the sequence of calls, so that two identical runs give byte-identical traces.
/// Times are simulated picoseconds. Calls arrive in non-decreasing time per track.
class TraceSink {
public:
  virtual ~TraceSink() = default;

  /// Declares a track; `group` is the node (a Perfetto process), `name` the row within it
  /// ("cpu", "link0 out", "memory"). Same (group, name) twice gives the same id.
  virtual TrackId track(std::string_view group, std::string_view name) = 0;
  /// Opens a slice (a process running, a link transfer) on a track.
  virtual void begin_slice(TrackId track, Tick at, std::string_view name) = 0;
  /// Closes the most recent open slice on a track.
  virtual void end_slice(TrackId track, Tick at) = 0;
  /// A sampled value, e.g. memory high-water mark in bytes.
  virtual void counter(TrackId track, Tick at, std::string_view name, std::int64_t value) = 0;
  /// A point event: fault, power change, deadlock.
  virtual void instant(TrackId track, Tick at, std::string_view name, std::string_view detail) = 0;
  /// Arrow from a point on one track to a point on another (a message over a link); the
  /// two calls share `flow_id`.
  virtual void flow_begin(TrackId track, Tick at, std::uint64_t flow_id) = 0;
  virtual void flow_end(TrackId track, Tick at, std::uint64_t flow_id) = 0;
};

} // namespace marsokhod::emulator
