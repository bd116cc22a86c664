// A trace sink that writes Chrome Trace Event JSON (Perfetto UI, chrome://tracing).
#pragma once

#include "marsokhod/emulator/trace/trace_sink.hpp"

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace marsokhod::emulator {

/// Writes trace records as Chrome Trace Event JSON (opens in Perfetto UI and chrome://tracing):
/// each group (node) is a process, each track a thread of it, slices are B/E pairs, counters C
/// events, instants i events, flows s/f pairs. Times are simulated microseconds with six
/// decimals (exact to the picosecond). Output depends only on the sequence of calls: pids and
/// tids are given in order of declaration.
class ChromeTraceWriter : public TraceSink {
public:
  /// Streams into `out`, which must outlive the writer.
  explicit ChromeTraceWriter(std::ostream& out);
  ~ChromeTraceWriter() override;
  ChromeTraceWriter(const ChromeTraceWriter&) = delete;
  ChromeTraceWriter& operator=(const ChromeTraceWriter&) = delete;

  TrackId track(std::string_view group, std::string_view name) override;
  void begin_slice(TrackId track, Tick at, std::string_view name) override;
  void end_slice(TrackId track, Tick at) override;
  void counter(TrackId track, Tick at, std::string_view name, std::int64_t value) override;
  void instant(TrackId track, Tick at, std::string_view name, std::string_view detail) override;
  void flow_begin(TrackId track, Tick at, std::uint64_t flow_id) override;
  void flow_end(TrackId track, Tick at, std::uint64_t flow_id) override;

  /// Closes slices still open (at their track's last time) and the JSON document; called by
  /// the destructor if not before. Nothing may be recorded afterwards.
  void close();
  std::uint64_t events_written() const { return events_; }

private:
  struct Track {
    int pid;
    int tid;
    std::string name;
    int open_slices = 0;
    Tick last_time = 0;
  };

  void emit(const std::string& event);
  std::string where(const Track& track, Tick at) const;
  Track& touch(TrackId track, Tick time);

  std::ostream& out_;
  std::map<std::string, int, std::less<>> groups_;
  std::map<std::pair<int, std::string>, TrackId, std::less<>> track_ids_;
  std::vector<Track> tracks_;
  std::vector<int> threads_per_group_;
  std::uint64_t events_ = 0;
  bool closed_ = false;
};

/// Microseconds with six decimals from picoseconds: 1'234'567 ps -> "1.234567".
std::string trace_timestamp(Tick at);

} // namespace marsokhod::emulator
