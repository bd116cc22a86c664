// The kernel's queue of pending events, ordered by time, priority and sequence.

#include "kernel/event_queue.hpp"

#include <algorithm>

namespace marsokhod::emulator::detail {

bool EventQueue::later(const Entry& a, const Entry& b) {
  if (a.time != b.time)
    return a.time > b.time;
  if (a.priority != b.priority)
    return a.priority > b.priority;
  return a.sequence > b.sequence;
}

EventId EventQueue::push(Tick at, EventPriority priority, EventHandler* handler, std::uint64_t tag,
                         std::function<void()> action, EventKind kind) {
  std::uint32_t index = 0;
  if (free_slots_.empty()) {
    index = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
  } else {
    index = free_slots_.back();
    free_slots_.pop_back();
  }
  Slot& slot = slots_[index];
  slot.handler = handler;
  slot.tag = tag;
  slot.action = std::move(action);
  slot.pending = true;
  slot.background = kind == EventKind::background;
  foreground_ += slot.background ? 0 : 1;
  ++live_;
  heap_.push_back(Entry{at, priority, index, next_sequence_++, slot.generation});
  std::push_heap(heap_.begin(), heap_.end(), later);
  return (static_cast<EventId>(slot.generation) << 32) | (index + 1);
}

void EventQueue::free_slot(std::uint32_t index) {
  Slot& slot = slots_[index];
  foreground_ -= slot.background ? 0 : 1;
  --live_;
  slot.pending = false;
  slot.action = nullptr;
  ++slot.generation;
  free_slots_.push_back(index);
}

bool EventQueue::cancel(EventId id) {
  const auto low = static_cast<std::uint32_t>(id & 0xffff'ffffU);
  if (low == 0 || low > slots_.size())
    return false;
  const std::uint32_t index = low - 1;
  const Slot& slot = slots_[index];
  if (!slot.pending || slot.generation != static_cast<std::uint32_t>(id >> 32))
    return false;
  free_slot(index);
  return true;
}

void EventQueue::drop_stale_top() {
  while (!heap_.empty() && stale(heap_.front())) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    heap_.pop_back();
  }
}

bool EventQueue::pop(Fired& out) {
  drop_stale_top();
  if (heap_.empty())
    return false;
  const Entry top = heap_.front();
  std::pop_heap(heap_.begin(), heap_.end(), later);
  heap_.pop_back();
  Slot& slot = slots_[top.slot];
  out.time = top.time;
  out.handler = slot.handler;
  out.tag = slot.tag;
  out.action = std::move(slot.action);
  free_slot(top.slot);
  return true;
}

} // namespace marsokhod::emulator::detail
