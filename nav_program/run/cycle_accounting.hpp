// CycleAccounting: the trace records of a cycle summed into CPU time per process, passed on to
// the user's trace when there is one.
#pragma once

// A trace sink in front of the user's (private to the layer). The kernel already
// records a slice per process run on each CPU track; summing them gives every process's CPU
// time exactly, without a second bookkeeping in the kernel's switch path.

#include "marsokhod/emulator/trace/trace_sink.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace marsokhod::nav_program::detail {

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

private:
  struct Track {
    std::string group;
    std::string name;
    bool cpu = false;
    emulator::TrackId next_id = 0;
    std::vector<std::pair<emulator::Tick, std::string>> open; // start and slice name
  };

  emulator::TraceSink* next_;
  std::vector<Track> tracks_;
  std::map<std::pair<std::string, std::string>, emulator::TrackId> ids_;
  std::map<std::pair<std::string, std::string>, emulator::Tick> cpu_;
};

} // namespace marsokhod::nav_program::detail
