// Summing a cycle's trace records into CPU time per process and traffic per link direction.

#include "navigation/cycle_accounting.hpp"

#include <charconv>

namespace marsokhod::occam_port::detail {
namespace {

// "out 512 bytes" -> 512.
std::uint64_t message_bytes(std::string_view slice) {
  constexpr std::string_view prefix = "out ";
  if (!slice.starts_with(prefix))
    return 0;
  slice.remove_prefix(prefix.size());
  std::uint64_t bytes = 0;
  std::from_chars(slice.data(), slice.data() + slice.size(), bytes);
  return bytes;
}

} // namespace

emulator::TrackId CycleAccounting::track(std::string_view group, std::string_view name) {
  const std::pair<std::string, std::string> key{group, name};
  if (const auto found = ids_.find(key); found != ids_.end())
    return found->second;
  Track made{key.first, key.second, Role::other, 0, {}};
  if (name == "cpu")
    made.role = Role::cpu;
  else if (name.starts_with("link") && name.ends_with(" out"))
    made.role = Role::link_output;
  if (next_ != nullptr)
    made.next_id = next_->track(group, name);
  const auto id = static_cast<emulator::TrackId>(tracks_.size());
  tracks_.push_back(std::move(made));
  ids_.emplace(key, id);
  return id;
}

void CycleAccounting::begin_slice(emulator::TrackId track, emulator::Tick at,
                                  std::string_view name) {
  Track& t = tracks_[track];
  if (t.role != Role::other)
    t.open.emplace_back(at, std::string(name));
  if (next_ != nullptr)
    next_->begin_slice(t.next_id, at, name);
}

void CycleAccounting::end_slice(emulator::TrackId track, emulator::Tick at) {
  Track& t = tracks_[track];
  if (t.role != Role::other && !t.open.empty()) {
    const auto [start, name] = std::move(t.open.back());
    t.open.pop_back();
    if (t.role == Role::cpu) {
      cpu_[{t.group, name}] += at - start;
    } else {
      Traffic& traffic = outputs_[t.group + "." + t.name.substr(0, t.name.size() - 4)];
      traffic.busy += at - start;
      traffic.bytes += message_bytes(name);
    }
  }
  if (next_ != nullptr)
    next_->end_slice(t.next_id, at);
}

void CycleAccounting::counter(emulator::TrackId track, emulator::Tick at, std::string_view name,
                              std::int64_t value) {
  if (next_ != nullptr)
    next_->counter(tracks_[track].next_id, at, name, value);
}

void CycleAccounting::instant(emulator::TrackId track, emulator::Tick at, std::string_view name,
                              std::string_view detail) {
  if (next_ != nullptr)
    next_->instant(tracks_[track].next_id, at, name, detail);
}

void CycleAccounting::flow_begin(emulator::TrackId track, emulator::Tick at,
                                 std::uint64_t flow_id) {
  if (next_ != nullptr)
    next_->flow_begin(tracks_[track].next_id, at, flow_id);
}

void CycleAccounting::flow_end(emulator::TrackId track, emulator::Tick at, std::uint64_t flow_id) {
  if (next_ != nullptr)
    next_->flow_end(tracks_[track].next_id, at, flow_id);
}

} // namespace marsokhod::occam_port::detail
