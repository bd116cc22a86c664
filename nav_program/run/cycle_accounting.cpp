// Summing a cycle's trace records into CPU time per process.

#include "run/cycle_accounting.hpp"

namespace marsokhod::nav_program::detail {

emulator::TrackId CycleAccounting::track(std::string_view group, std::string_view name) {
  const std::pair<std::string, std::string> key{group, name};
  if (const auto found = ids_.find(key); found != ids_.end())
    return found->second;
  Track made{key.first, key.second, name == "cpu", 0, {}};
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
  if (t.cpu)
    t.open.emplace_back(at, std::string(name));
  if (next_ != nullptr)
    next_->begin_slice(t.next_id, at, name);
}

void CycleAccounting::end_slice(emulator::TrackId track, emulator::Tick at) {
  Track& t = tracks_[track];
  if (t.cpu && !t.open.empty()) {
    cpu_[{t.group, t.open.back().second}] += at - t.open.back().first;
    t.open.pop_back();
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

} // namespace marsokhod::nav_program::detail
