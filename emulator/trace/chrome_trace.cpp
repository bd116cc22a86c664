// Trace records written as Chrome Trace Event JSON.

#include "marsokhod/emulator/trace/chrome_trace.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <stdexcept>

namespace marsokhod::emulator {
namespace {

std::string json_string(std::string_view text) {
  return nlohmann::json(std::string(text)).dump();
}

} // namespace

std::string trace_timestamp(Tick at) {
  const char* sign = at < 0 ? "-" : "";
  const std::uint64_t magnitude =
      at < 0 ? 0 - static_cast<std::uint64_t>(at) : static_cast<std::uint64_t>(at);
  return fmt::format("{}{}.{:06}", sign, magnitude / 1'000'000, magnitude % 1'000'000);
}

ChromeTraceWriter::ChromeTraceWriter(std::ostream& out) : out_(out) {
  out_ << "{\"displayTimeUnit\":\"ns\",\"traceEvents\":[";
}

ChromeTraceWriter::~ChromeTraceWriter() {
  close();
}

void ChromeTraceWriter::emit(const std::string& event) {
  if (closed_)
    throw std::logic_error("trace record after the trace was closed");
  out_ << (events_ == 0 ? "\n" : ",\n") << event;
  ++events_;
}

std::string ChromeTraceWriter::where(const Track& track, Tick at) const {
  return fmt::format("\"pid\":{},\"tid\":{},\"ts\":{}", track.pid, track.tid, trace_timestamp(at));
}

ChromeTraceWriter::Track& ChromeTraceWriter::touch(TrackId track, Tick time) {
  if (track >= tracks_.size())
    throw std::out_of_range(fmt::format("trace track {} was never declared", track));
  Track& found = tracks_[track];
  found.last_time = std::max(found.last_time, time);
  return found;
}

TrackId ChromeTraceWriter::track(std::string_view group, std::string_view name) {
  auto group_it = groups_.find(group);
  if (group_it == groups_.end()) {
    const int pid = static_cast<int>(groups_.size()) + 1;
    group_it = groups_.emplace(std::string(group), pid).first;
    threads_per_group_.push_back(0);
    emit(fmt::format(R"({{"ph":"M","name":"process_name","pid":{},"args":{{"name":{}}}}})", pid,
                     json_string(group)));
    emit(fmt::format(
        R"({{"ph":"M","name":"process_sort_index","pid":{},"args":{{"sort_index":{}}}}})", pid,
        pid));
  }
  const int pid = group_it->second;
  const auto key = std::make_pair(pid, std::string(name));
  if (const auto found = track_ids_.find(key); found != track_ids_.end())
    return found->second;
  const int tid = ++threads_per_group_[static_cast<std::size_t>(pid - 1)];
  const auto id = static_cast<TrackId>(tracks_.size());
  tracks_.push_back(Track{pid, tid, std::string(name)});
  track_ids_.emplace(key, id);
  emit(fmt::format(R"({{"ph":"M","name":"thread_name","pid":{},"tid":{},"args":{{"name":{}}}}})",
                   pid, tid, json_string(name)));
  emit(fmt::format(
      R"({{"ph":"M","name":"thread_sort_index","pid":{},"tid":{},"args":{{"sort_index":{}}}}})",
      pid, tid, tid));
  return id;
}

void ChromeTraceWriter::begin_slice(TrackId track, Tick time, std::string_view name) {
  Track& t = touch(track, time);
  ++t.open_slices;
  emit(fmt::format(R"({{"ph":"B",{},"name":{}}})", where(t, time), json_string(name)));
}

void ChromeTraceWriter::end_slice(TrackId track, Tick time) {
  Track& t = touch(track, time);
  if (t.open_slices == 0)
    return; // nothing open: a viewer would reject an unmatched E
  --t.open_slices;
  emit(fmt::format(R"({{"ph":"E",{}}})", where(t, time)));
}

void ChromeTraceWriter::counter(TrackId track, Tick time, std::string_view name,
                                std::int64_t value) {
  const Track& t = touch(track, time);
  emit(fmt::format(R"({{"ph":"C",{},"name":{},"args":{{{}:{}}}}})", where(t, time),
                   json_string(t.name), json_string(name), value));
}

void ChromeTraceWriter::instant(TrackId track, Tick time, std::string_view name,
                                std::string_view detail) {
  const Track& t = touch(track, time);
  emit(fmt::format(R"({{"ph":"i","s":"t",{},"name":{},"args":{{"detail":{}}}}})", where(t, time),
                   json_string(name), json_string(detail)));
}

void ChromeTraceWriter::flow_begin(TrackId track, Tick time, std::uint64_t flow_id) {
  const Track& t = touch(track, time);
  emit(fmt::format(R"({{"ph":"s","cat":"link","name":"message","id":{},{}}})", flow_id,
                   where(t, time)));
}

void ChromeTraceWriter::flow_end(TrackId track, Tick time, std::uint64_t flow_id) {
  const Track& t = touch(track, time);
  emit(fmt::format(R"({{"ph":"f","bp":"e","cat":"link","name":"message","id":{},{}}})", flow_id,
                   where(t, time)));
}

void ChromeTraceWriter::close() {
  if (closed_)
    return;
  for (Track& t : tracks_)
    for (; t.open_slices > 0; --t.open_slices)
      emit(fmt::format(R"({{"ph":"E",{}}})", where(t, t.last_time)));
  closed_ = true;
  out_ << "\n]}\n";
  out_.flush();
}

} // namespace marsokhod::emulator
