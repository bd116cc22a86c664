// A node's end of a link as its processes see it: outputs and inputs over the wire.

#include "marsokhod/emulator/links/link.hpp"

#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <utility>

namespace marsokhod::emulator {
namespace {

Process& current_process(Kernel& kernel, const std::string& port) {
  Process* self = kernel.current();
  if (self == nullptr)
    throw std::logic_error(fmt::format("blocking transfer on {} outside a process", port));
  return *self;
}

/// Gives up a transfer when its process is killed while blocked on it (power-off, end of the
/// simulation), so that no later event calls back into the unwound stack frame.
class AbandonOnUnwind {
public:
  AbandonOnUnwind(const bool& done, std::weak_ptr<int> link_alive, std::function<void()> abandon)
      : done_(done), link_alive_(std::move(link_alive)), abandon_(std::move(abandon)) {}
  ~AbandonOnUnwind() {
    if (!done_ && !link_alive_.expired())
      abandon_();
  }
  AbandonOnUnwind(const AbandonOnUnwind&) = delete;
  AbandonOnUnwind& operator=(const AbandonOnUnwind&) = delete;

private:
  const bool& done_;
  std::weak_ptr<int> link_alive_;
  std::function<void()> abandon_;
};

} // namespace

// A reset overwrites the result with "cut short" before it wakes the process.
LinkTransferResult LinkPort::output(std::span<const std::byte> message) {
  Kernel& kernel = link_->kernel();
  Process& self = current_process(kernel, name_);
  LinkTransferResult result{true, message.size()};
  bool done = false;
  begin_output(
      message,
      [&] {
        done = true;
        kernel.wake(self);
      },
      &result);
  AbandonOnUnwind guard(done, link_->alive_, [this] { abandon_output(); });
  while (!done)
    kernel.block(WaitInfo{WaitKind::link_output, this});
  return result;
}

LinkTransferResult LinkPort::input(std::span<std::byte> buffer) {
  Kernel& kernel = link_->kernel();
  Process& self = current_process(kernel, name_);
  LinkTransferResult result{true, buffer.size()};
  bool done = false;
  begin_input(
      buffer,
      [&] {
        done = true;
        kernel.wake(self);
      },
      &result);
  AbandonOnUnwind guard(done, link_->alive_, [this] { abandon_input(); });
  while (!done)
    kernel.block(WaitInfo{WaitKind::link_input, this});
  return result;
}

void LinkPort::start_output(std::span<const std::byte> message, Done done) {
  begin_output(message, std::move(done), nullptr);
}

void LinkPort::start_input(std::span<std::byte> buffer, Done done) {
  begin_input(buffer, std::move(done), nullptr);
}

void LinkPort::begin_output(std::span<const std::byte> message, Done done,
                            LinkTransferResult* report) {
  if (output_.active)
    throw std::logic_error(fmt::format("{}: an output is already in progress", name_));
  if (message.empty()) {
    done();
    return;
  }
  Kernel& kernel = link_->kernel();
  output_ = Transfer{true, {}, message, 0, 0, link_->next_flow_id(), std::move(done), report};
  output_since_ = kernel.now();
  if (TraceSink* sink = link_->trace()) {
    sink->begin_slice(out_track_, kernel.now(), fmt::format("out {} bytes", message.size()));
    sink->flow_begin(out_track_, kernel.now(), output_.flow);
  }
  link_->framing_.offer_output(end_, kernel.now(), message.size());
  link_->reschedule();
}

void LinkPort::begin_input(std::span<std::byte> buffer, Done done, LinkTransferResult* report) {
  if (input_.active)
    throw std::logic_error(fmt::format("{}: an input is already in progress", name_));
  if (buffer.empty()) {
    done();
    return;
  }
  Kernel& kernel = link_->kernel();
  input_ = Transfer{true, buffer, {}, 0, 0, 0, std::move(done), report};
  if (TraceSink* sink = link_->trace())
    sink->begin_slice(in_track_, kernel.now(), fmt::format("in {} bytes", buffer.size()));
  if (link_->framing_.offer_input(end_, kernel.now(), buffer.size())) {
    input_.in[input_.done++] = held_;
    if (input_.done == input_.in.size())
      finish(input_, in_track_);
  }
  link_->reschedule();
}

void LinkPort::finish(Transfer& transfer, TrackId track) {
  if (&transfer == &output_)
    count_output();
  Done done = std::move(transfer.on_done);
  transfer = Transfer{};
  if (TraceSink* sink = link_->trace())
    sink->end_slice(track, link_->kernel().now());
  if (done)
    done();
}

void LinkPort::cut_short(Transfer& transfer, TrackId track) {
  if (&transfer == &output_)
    count_output();
  Transfer ended = std::exchange(transfer, Transfer{});
  if (TraceSink* sink = link_->trace())
    sink->end_slice(track, link_->kernel().now());
  if (ended.report == nullptr)
    return;
  *ended.report = LinkTransferResult{false, ended.done};
  if (ended.on_done)
    ended.on_done();
}

bool LinkPort::reset_output() {
  const Tick now = link_->kernel().now();
  if (TraceSink* sink = link_->trace())
    sink->instant(out_track_, now, "resetch", name_ + " out");
  link_->framing_.reset_output(end_, now);
  const bool cut = output_.active;
  if (cut)
    cut_short(output_, out_track_);
  link_->reschedule();
  return cut;
}

bool LinkPort::reset_input() {
  const Tick now = link_->kernel().now();
  if (TraceSink* sink = link_->trace())
    sink->instant(in_track_, now, "resetch", name_ + " in");
  link_->framing_.reset_input(end_, now);
  const bool cut = input_.active;
  if (cut)
    cut_short(input_, in_track_);
  link_->reschedule();
  return cut;
}

bool LinkPort::reset() {
  const bool output_cut = reset_output();
  const bool input_cut = reset_input();
  return output_cut || input_cut;
}

void LinkPort::count_output() {
  bytes_sent_ += output_.done;
  output_busy_ += link_->kernel().now() - output_since_;
}

void LinkPort::abandon_output() {
  count_output();
  link_->framing_.withdraw_output(end_);
  output_ = Transfer{};
  if (TraceSink* sink = link_->trace())
    sink->end_slice(out_track_, link_->kernel().now());
}

void LinkPort::abandon_input() {
  link_->framing_.withdraw_input(end_);
  input_ = Transfer{};
  if (TraceSink* sink = link_->trace())
    sink->end_slice(in_track_, link_->kernel().now());
}

bool LinkPort::byte_waiting() const {
  return link_->framing_.byte_waiting(end_);
}

void LinkPort::set_arrival_listener(std::function<void()> listener) {
  arrival_listener_ = std::move(listener);
}

std::string LinkPort::describe() const {
  std::string text = "link " + name_;
  if (output_.active)
    text += fmt::format(", output: {} of {} bytes unacknowledged",
                        output_.out.size() - output_.done, output_.out.size());
  if (input_.active)
    text += fmt::format(", input: {} of {} bytes still to come", input_.in.size() - input_.done,
                        input_.in.size());
  return text;
}

} // namespace marsokhod::emulator
