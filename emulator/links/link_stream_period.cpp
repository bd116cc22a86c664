// A one-way stream on a link repeats one byte period: finding the period and jumping it.

#include "marsokhod/emulator/links/link_framing.hpp"

#include <algorithm>
#include <utility>

namespace marsokhod::emulator {
namespace {

// A time that only ever bounds a later one from below (max with now): a past one is now.
Tick relative_bound(Tick at, Tick now) {
  return at == kNever ? kNever : std::max(at, now) - now;
}

Tick relative_end(Tick at, Tick now) {
  return at == kNever ? kNever : at - now;
}

// Moves on a pending time; a past bound stays where it is, which means now as much as before.
void shift_bound(Tick& at, Tick now, Tick shift) {
  if (at != kNever && at >= now)
    at += shift;
}

} // namespace

LinkFraming::Phase LinkFraming::phase_at_now() const {
  Phase phase;
  phase.valid = true;
  phase.generation = generation_;
  phase.at = now_;
  for (int end = 0; end < 2; ++end) {
    End e = ends_[end];
    e.next_data_allowed = relative_bound(e.next_data_allowed, now_);
    e.wire_free = relative_bound(e.wire_free, now_);
    e.ack_ready = relative_bound(e.ack_ready, now_);
    // The start bit matters only while its packet is on the wire, as the earliest acknowledge.
    e.data_start =
        e.data_end == kNever ? 0 : relative_bound(e.data_start + timing_.ack_delay, now_);
    e.data_end = relative_end(e.data_end, now_);
    e.ack_end = relative_end(e.ack_end, now_);
    phase.ends[static_cast<std::size_t>(end)] = e;
  }
  return phase;
}

std::optional<Tick> LinkFraming::stream_period(int sender) {
  const Phase now = phase_at_now();
  const Phase before = std::exchange(last_data_start_[static_cast<std::size_t>(sender)], now);
  if (!before.valid || before.generation != generation_)
    return std::nullopt;
  // A dead wire or an acknowledge still to be lost stops the stream within a byte: no jump
  // may carry it past that.
  if (wire_dead_[0] || wire_dead_[1] || acks_to_lose_[static_cast<std::size_t>(1 - sender)] > 0)
    return std::nullopt;
  Phase expected = before;
  End& out = expected.ends[static_cast<std::size_t>(sender)];
  End& in = expected.ends[static_cast<std::size_t>(1 - sender)];
  if (out.queued == 0 || in.accept_budget == 0)
    return std::nullopt;
  --out.queued;
  --in.accept_budget;
  if (expected.ends != now.ends)
    return std::nullopt;
  return now.at - before.at;
}

std::uint64_t LinkFraming::skippable_bytes(int sender) const {
  const std::uint64_t to_send = ends_[static_cast<std::size_t>(sender)].queued;
  const std::uint64_t to_take = ends_[static_cast<std::size_t>(1 - sender)].accept_budget;
  const std::uint64_t left = std::min(to_send, to_take);
  return left > 0 ? left - 1 : 0;
}

void LinkFraming::skip_stream(int sender, std::uint64_t bytes, Tick period) {
  const Tick shift = static_cast<Tick>(bytes) * period;
  for (End& e : ends_) {
    if (e.data_end != kNever && e.data_start + timing_.ack_delay > now_)
      e.data_start += shift;
    shift_bound(e.next_data_allowed, now_, shift);
    shift_bound(e.wire_free, now_, shift);
    shift_bound(e.ack_ready, now_, shift);
    shift_bound(e.data_end, now_, shift);
    shift_bound(e.ack_end, now_, shift);
  }
  ends_[static_cast<std::size_t>(sender)].queued -= bytes;
  ends_[static_cast<std::size_t>(1 - sender)].accept_budget -= bytes;
  now_ += shift;
  Phase& last = last_data_start_[static_cast<std::size_t>(sender)];
  last.at = now_;
  last.ends[static_cast<std::size_t>(sender)].queued -= bytes;
  last.ends[static_cast<std::size_t>(1 - sender)].accept_budget -= bytes;
}

} // namespace marsokhod::emulator
