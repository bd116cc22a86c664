// The kernel's queue of pending events, ordered by time, priority and sequence.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace marsokhod::emulator::detail {

/// Pending events ordered by (time, priority, sequence). Cancellation is O(1): the slot is
/// freed at once and its heap entry is skipped when it surfaces.
class EventQueue {
public:
  /// What a popped event does.
  struct Fired {
    Tick time = 0;
    EventHandler* handler = nullptr;
    std::uint64_t tag = 0;
    std::function<void()> action;
  };

  EventId push(Tick at, EventPriority priority, EventHandler* handler, std::uint64_t tag,
               std::function<void()> action, EventKind kind);
  bool cancel(EventId id);
  /// Time of the earliest live event, kNever if none.
  Tick next_time() {
    if (heap_.empty())
      return kNever;
    if (!stale(heap_.front()))
      return heap_.front().time;
    drop_stale_top();
    return heap_.empty() ? kNever : heap_.front().time;
  }
  /// Removes the earliest live event; false when there is none.
  bool pop(Fired& out);
  std::size_t foreground() const { return foreground_; }
  std::size_t size() const { return live_; }

private:
  struct Entry {
    Tick time;
    EventPriority priority;
    std::uint32_t slot;
    std::uint64_t sequence;
    std::uint32_t generation;
  };
  struct Slot {
    EventHandler* handler = nullptr;
    std::uint64_t tag = 0;
    std::function<void()> action;
    std::uint32_t generation = 1;
    bool pending = false;
    bool background = false;
  };
  static bool later(const Entry& a, const Entry& b);
  bool stale(const Entry& e) const {
    const Slot& slot = slots_[e.slot];
    return !slot.pending || slot.generation != e.generation;
  }
  void free_slot(std::uint32_t slot);
  void drop_stale_top();

  std::vector<Entry> heap_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_slots_;
  std::uint64_t next_sequence_ = 0;
  std::size_t foreground_ = 0;
  std::size_t live_ = 0;
};

} // namespace marsokhod::emulator::detail
