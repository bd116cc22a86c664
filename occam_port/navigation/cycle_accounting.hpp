// CycleAccounting: the trace records of a cycle summed into CPU time per process and link
// traffic per direction, passed on to the user's trace when there is one.
#pragma once

// A trace sink in front of the user's (private to the navigation room). The kernel already
// records a slice per process run on each CPU track and a slice per message on each link
// direction's track ("out N bytes"); summing them gives every process's CPU time and every
// link direction's busy time and bytes exactly, without a second bookkeeping in the kernel.

#include "marsokhod/emulator/trace/trace_sink.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace marsokhod::occam_port::detail {

class CycleAccounting final : public emulator::TraceSink {
public:
  /// `next` (may be null) receives every record unchanged.
  explicit CycleAccounting(emulator::TraceSink* next) : next_(next) {}

  emulator::TrackId track(std::string_view group, std::string_view name) override;
  void begin_slice(emulator::TrackId track, emulator::Tick at, std::string_view name) override;
  void end_slice(emulator::TrackId track, emulator::Tick at) override;
  void counter(emulator::TrackId track, emulator::Tick at, std::string_view name,
               std::int64_t value) override;
  void instant(emulator::TrackId track, emulator::Tick at, std::string_view name,
               std::string_view detail) override;
  void flow_begin(emulator::TrackId track, emulator::Tick at, std::uint64_t flow_id) override;
  void flow_end(emulator::TrackId track, emulator::Tick at, std::uint64_t flow_id) override;

  /// Simulated CPU time each (node, process) held its CPU.
  const std::map<std::pair<std::string, std::string>, emulator::Tick>& cpu_time() const {
    return cpu_;
  }
  /// Busy time and bytes of each link output, keyed by its port ("module0.link2").
  struct Traffic {
    emulator::Tick busy = 0;
    std::uint64_t bytes = 0;
  };
  const std::map<std::string, Traffic>& link_outputs() const { return outputs_; }
  /// The user's track for (group, name), for records the program adds itself; 0 without one.
  emulator::TrackId forward_track(emulator::TrackId track) const { return tracks_[track].next_id; }

private:
  enum class Role : std::uint8_t { other, cpu, link_output };
  struct Track {
    std::string group;
    std::string name;
    Role role = Role::other;
    emulator::TrackId next_id = 0;
    std::vector<std::pair<emulator::Tick, std::string>> open; // start and slice name
  };

  emulator::TraceSink* next_;
  std::vector<Track> tracks_;
  std::map<std::pair<std::string, std::string>, emulator::TrackId> ids_;
  std::map<std::pair<std::string, std::string>, emulator::Tick> cpu_;
  std::map<std::string, Traffic> outputs_;
};

} // namespace marsokhod::occam_port::detail
