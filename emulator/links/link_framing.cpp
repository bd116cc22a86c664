// The handshake timing of a link: data and acknowledge packets, bit by bit.

#include "marsokhod/emulator/links/link_framing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace marsokhod::emulator {
namespace {

Tick bits_to_ticks(double bits, Tick bit) {
  return static_cast<Tick>(std::llround(bits * static_cast<double>(bit)));
}

} // namespace

LinkTiming LinkTiming::from(const LinkTimingSpec& spec, int mbps) {
  if (mbps <= 0)
    throw std::invalid_argument("link speed must be positive");
  LinkTiming timing;
  timing.bit = kSecond / (static_cast<Tick>(mbps) * 1'000'000);
  timing.data_packet = bits_to_ticks(spec.data_packet_bits, timing.bit);
  timing.ack_packet = bits_to_ticks(spec.ack_packet_bits, timing.bit);
  timing.ack_delay = bits_to_ticks(spec.ack_delay_bits, timing.bit);
  timing.ack_turnaround =
      bits_to_ticks(spec.ack_turnaround_bits, timing.bit) + spec.ack_turnaround_fixed;
  timing.gap = bits_to_ticks(spec.inter_packet_gap_bits, timing.bit);
  return timing;
}

LinkFraming::LinkFraming(const LinkTiming& timing) : timing_(timing) {}

void LinkFraming::offer_output(int end, Tick now, std::uint64_t bytes) {
  ++generation_;
  now_ = std::max(now_, now);
  ends_[end].queued += bytes;
}

bool LinkFraming::offer_input(int end, Tick now, std::uint64_t bytes) {
  ++generation_;
  now_ = std::max(now_, now);
  End& receiver = ends_[end];
  receiver.accept_budget += bytes;
  bool took_waiting_byte = false;
  if (receiver.holding && receiver.accept_budget > 0) {
    receiver.holding = false;
    --receiver.accept_budget;
    receiver.ack_owed = true;
    receiver.ack_ready = now_;
    took_waiting_byte = true;
  }
  accept_in_flight(end);
  return took_waiting_byte;
}

std::uint64_t LinkFraming::output_left(int end) const {
  return ends_[end].queued + (ends_[end].awaiting_ack ? 1 : 0);
}

void LinkFraming::accept_in_flight(int receiver) {
  End& sender = ends_[1 - receiver];
  End& self = ends_[receiver];
  if (sender.data_end == kNever || sender.data_accepted || sender.data_lost ||
      self.accept_budget == 0 || !self.alive)
    return;
  --self.accept_budget;
  sender.data_accepted = true;
  self.ack_owed = true;
  self.ack_ready = std::max(now_, sender.data_start + timing_.ack_delay);
}

void LinkFraming::reset_end(int end, Tick now, bool alive) {
  ++generation_;
  now_ = std::max(now_, now);
  const Tick wire_free = now_;
  ends_[end] = End{};
  ends_[end].alive = alive;
  ends_[end].wire_free = wire_free;
  ends_[end].next_data_allowed = wire_free;
}

void LinkFraming::reset_output(int end, Tick now) {
  ++generation_;
  now_ = std::max(now_, now);
  End& self = ends_[end];
  self.queued = 0;
  self.awaiting_ack = false;
}

void LinkFraming::reset_input(int end, Tick now) {
  ++generation_;
  now_ = std::max(now_, now);
  End& self = ends_[end];
  End& sender = ends_[1 - end];
  self.accept_budget = 0;
  self.holding = false;
  self.ack_owed = false;
  self.ack_ready = kNever;
  if (sender.data_end != kNever && sender.data_accepted)
    sender.data_dropped = true;
}

bool LinkFraming::start_data(int sender, Tick at) {
  End& self = ends_[sender];
  --self.queued;
  self.awaiting_ack = true;
  self.data_start = at;
  self.data_end = at + timing_.data_packet;
  self.data_accepted = false;
  self.data_lost = wire_dead_[sender];
  self.data_dropped = false;
  self.wire_free = self.data_end + timing_.gap;
  accept_in_flight(1 - sender);
  return self.data_lost;
}

void LinkFraming::end_data(int sender, LinkStep& step) {
  End& self = ends_[sender];
  End& receiver = ends_[1 - sender];
  self.data_end = kNever;
  step.accepted = self.data_accepted && !self.data_dropped;
  if (!self.data_accepted && !self.data_lost && receiver.alive)
    receiver.holding = true;
  self.data_lost = false;
  self.data_dropped = false;
}

bool LinkFraming::start_ack(int receiver, Tick at) {
  End& self = ends_[receiver];
  self.ack_owed = false;
  self.ack_ready = kNever;
  self.ack_end = at + timing_.ack_packet;
  self.wire_free = self.ack_end + timing_.gap;
  self.ack_lost = wire_dead_[receiver];
  if (acks_to_lose_[receiver] > 0) {
    --acks_to_lose_[receiver];
    self.ack_lost = true;
  }
  return self.ack_lost;
}

void LinkFraming::end_ack(int receiver, LinkStep& step) {
  End& self = ends_[receiver];
  End& sender = ends_[1 - receiver];
  self.ack_end = kNever;
  step.end = 1 - receiver;
  if (std::exchange(self.ack_lost, false) || !sender.alive || !sender.awaiting_ack)
    return;
  step.accepted = true;
  sender.awaiting_ack = false;
  sender.next_data_allowed = step.time + timing_.ack_turnaround;
}

LinkStep LinkFraming::step() {
  using Kind = LinkStep::Kind;
  LinkStep best;
  best.time = kNever;
  auto consider = [&](Kind kind, int end, Tick at) {
    if (at < best.time) {
      best.kind = kind;
      best.end = end;
      best.time = at;
    }
  };
  for (int end = 0; end < 2; ++end)
    consider(Kind::data_end, end, ends_[end].data_end);
  for (int end = 0; end < 2; ++end)
    consider(Kind::ack_end, end, ends_[end].ack_end);
  for (int end = 0; end < 2; ++end)
    consider(Kind::ack_start, end, ack_start_time(end));
  for (int end = 0; end < 2; ++end)
    consider(Kind::data_start, end, data_start_time(end));
  if (best.kind == Kind::none)
    return LinkStep{};
  now_ = best.time;
  switch (best.kind) {
  case Kind::data_end:
    end_data(best.end, best);
    break;
  case Kind::ack_end:
    end_ack(best.end, best);
    break;
  case Kind::ack_start:
    best.lost = start_ack(best.end, best.time);
    break;
  case Kind::data_start:
    best.lost = start_data(best.end, best.time);
    break;
  case Kind::none:
    break;
  }
  return best;
}

} // namespace marsokhod::emulator
