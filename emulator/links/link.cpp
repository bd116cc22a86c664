// A T805 link: the wire between two ends, its handshake steps, power and breaks.

#include "marsokhod/emulator/links/link.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

namespace marsokhod::emulator {
namespace {

std::pair<std::string, std::string> split_port_name(const std::string& name) {
  const auto dot = name.rfind('.');
  if (dot == std::string::npos)
    return {name, name};
  return {name.substr(0, dot), name.substr(dot + 1)};
}

} // namespace

Link::Link(Kernel& kernel, std::string end0, std::string end1, const LinkTiming& timing,
           std::uint32_t id)
    : kernel_(&kernel), framing_(timing), id_(id) {
  ports_[0].name_ = std::move(end0);
  ports_[1].name_ = std::move(end1);
  for (int end = 0; end < 2; ++end) {
    ports_[end].link_ = this;
    ports_[end].end_ = end;
  }
}

Link::~Link() {
  if (event_ != 0)
    kernel_->cancel(event_);
}

void Link::declare_tracks(TraceSink& sink) {
  if (tracks_declared_)
    return;
  tracks_declared_ = true;
  for (LinkPort& port : ports_) {
    const auto [group, link] = split_port_name(port.name_);
    port.out_track_ = sink.track(group, link + " out");
    port.in_track_ = sink.track(group, link + " in");
  }
}

TraceSink* Link::trace() {
  TraceSink* sink = kernel_->trace();
  if (sink != nullptr)
    declare_tracks(*sink);
  return sink;
}

void Link::set_powered(int end, bool powered) {
  if (framing_.alive(end) == powered)
    return;
  framing_.reset_end(end, kernel_->now(), powered);
  LinkPort& port = ports_[end];
  if (port.output_.active)
    port.count_output();
  TraceSink* sink = trace();
  if (sink != nullptr && port.output_.active)
    sink->end_slice(port.out_track_, kernel_->now());
  if (sink != nullptr && port.input_.active)
    sink->end_slice(port.in_track_, kernel_->now());
  port.output_ = LinkPort::Transfer{};
  port.input_ = LinkPort::Transfer{};
  port.arrival_listener_ = nullptr;
  if (sink != nullptr)
    sink->instant(port.out_track_, kernel_->now(), powered ? "link up" : "link down", port.name_);
  reschedule();
}

void Link::set_broken(bool broken) {
  framing_.set_broken(broken);
  if (TraceSink* sink = trace())
    sink->instant(ports_[0].out_track_, kernel_->now(), broken ? "cable broken" : "cable mended",
                  ports_[0].name_ + " - " + ports_[1].name_);
  reschedule();
}

void Link::reschedule() {
  schedule_next(framing_.next_time());
}

void Link::schedule_next(Tick next) {
  if (next == event_time_)
    return;
  if (event_ != 0)
    kernel_->cancel(event_);
  event_ = 0;
  event_time_ = next;
  if (next != kNever)
    event_ = kernel_->schedule_at(next, event_priority::link, *this);
}

// A message is a long chain of packet steps; while nothing else is due in between, the steps
// are taken here one after the other rather than each through the event queue.
void Link::on_event(std::uint64_t /*tag*/) {
  event_ = 0;
  event_time_ = kNever;
  Tick next = framing_.next_time();
  for (;;) {
    while (next <= kernel_->now()) {
      const LinkStep step = framing_.step();
      handle(step);
      if (step.kind == LinkStep::Kind::data_start)
        jump_stream(step.end);
      next = framing_.next_time();
    }
    if (next == kNever || !kernel_->advance_to_next_step(next))
      break;
  }
  schedule_next(next);
}

// A message's bytes follow one another at one period; once the framing finds the period, the
// whole periods before the message's last byte, and before anything else is due, are jumped:
// the bytes land in the input as the packet steps would have put them there.
void Link::jump_stream(int sender) {
  const std::optional<Tick> period = framing_.stream_period(sender);
  if (!period || *period <= 0)
    return;
  LinkPort::Transfer& out = ports_[sender].output_;
  LinkPort::Transfer& in = ports_[1 - sender].input_;
  if (!out.active || !in.active || out.started >= out.out.size() || in.done >= in.in.size())
    return;
  const Tick now = kernel_->now();
  const Tick bound = kernel_->inline_step_bound();
  if (bound <= now)
    return;
  const std::uint64_t in_time = static_cast<std::uint64_t>((bound - 1 - now) / *period);
  std::uint64_t bytes = std::min({framing_.skippable_bytes(sender), in_time,
                                  static_cast<std::uint64_t>(out.out.size() - out.started - 1),
                                  static_cast<std::uint64_t>(in.in.size() - in.done - 1)});
  // A byte due to be flipped is stepped, so that on_data_start() flips it.
  if (!flips_[sender].empty())
    bytes = std::min(bytes, bytes_before_flip(sender));
  if (bytes == 0 || !kernel_->advance_to_next_step(now + static_cast<Tick>(bytes) * *period))
    return;
  // The byte on the wire arrives first, then the next bytes - 1; the last one jumped is then
  // on the wire.
  in.in[in.done] = on_wire_[sender];
  std::copy_n(out.out.begin() + static_cast<std::ptrdiff_t>(out.started), bytes - 1,
              in.in.begin() + static_cast<std::ptrdiff_t>(in.done + 1));
  on_wire_[sender] = out.out[out.started + bytes - 1];
  out.started += bytes;
  out.done += bytes;
  in.done += bytes;
  data_started_[sender] += bytes;
  framing_.skip_stream(sender, bytes, *period);
}

void Link::handle(const LinkStep& step) {
  switch (step.kind) {
  case LinkStep::Kind::data_start:
    on_data_start(step.end);
    break;
  case LinkStep::Kind::data_end:
    on_data_end(step.end, step.accepted);
    break;
  case LinkStep::Kind::ack_end:
    if (step.accepted)
      on_ack_end(step.end);
    break;
  case LinkStep::Kind::ack_start:
    if (step.lost)
      note_lost_acknowledge(step.end);
    break;
  case LinkStep::Kind::none:
    break;
  }
}

void Link::on_data_start(int sender) {
  LinkPort::Transfer& out = ports_[sender].output_;
  on_wire_[sender] = out.out[out.started++];
  last_byte_flow_[sender] = out.started == out.out.size() ? out.flow : 0;
  const std::uint64_t byte = data_started_[sender]++;
  if (!flips_[sender].empty()) [[unlikely]]
    apply_flips(sender, byte);
}

void Link::on_data_end(int sender, bool accepted) {
  LinkPort& receiver = ports_[1 - sender];
  const std::uint64_t flow = std::exchange(last_byte_flow_[sender], 0);
  if (flow != 0)
    if (TraceSink* sink = trace())
      sink->flow_end(receiver.in_track_, kernel_->now(), flow);
  if (accepted) {
    LinkPort::Transfer& in = receiver.input_;
    if (!in.active)
      return; // its input was given up while the byte was on the wire
    in.in[in.done++] = on_wire_[sender];
    if (in.done == in.in.size())
      receiver.finish(in, receiver.in_track_);
    return;
  }
  if (!framing_.byte_waiting(1 - sender))
    return; // lost on a broken cable or at a powered-off node
  receiver.held_ = on_wire_[sender];
  if (receiver.arrival_listener_)
    receiver.arrival_listener_();
}

void Link::on_ack_end(int sender) {
  LinkPort& port = ports_[sender];
  LinkPort::Transfer& out = port.output_;
  if (!out.active || out.done >= out.started)
    return; // the acknowledge of a byte whose output was given up
  if (++out.done == out.out.size())
    port.finish(out, port.out_track_);
}

std::uint64_t Link::next_flow_id() {
  return (std::uint64_t{id_} << 32) | ++messages_;
}

} // namespace marsokhod::emulator
