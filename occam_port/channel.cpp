#include "marsokhod/occam_port/channel.hpp"

#include "marsokhod/emulator/link.hpp"
#include "marsokhod/emulator/node.hpp"
#include "marsokhod/occam_port/alt.hpp"

#include <span>
#include <stdexcept>
#include <utility>

namespace marsokhod::occam_port {

namespace {

using emulator::Instruction;
using emulator::Kernel;
using emulator::Node;
using emulator::Process;

std::uint64_t words(std::size_t bytes) {
  return (bytes + 3) / 4;
}

/// Cycles of `c ! x` or `c ? x` as compiled occam runs it: the operands are loaded (ldlp of
/// the message, ldl of the channel word, ldc of the length), then in/out moves w words. On a
/// link (`copied_words` 0) in/out only hand the message to the link's DMA engine, which moves
/// the bytes without the CPU: the base cost alone.
std::uint64_t channel_cycles(const Node& node, Instruction op, std::uint64_t copied_words) {
  const emulator::CostTable& costs = node.cpu_spec().costs;
  const auto cycles = [&costs](Instruction i) { return static_cast<std::uint64_t>(costs[i].base); };
  return cycles(Instruction::ldlp) + cycles(Instruction::ldl) + cycles(Instruction::ldc) +
         cycles(op) + copied_words * static_cast<std::uint64_t>(costs[op].per_unit);
}

/// The process executing a channel operation, its node and kernel.
struct Here {
  Kernel& kernel;
  Process& process;
  Node& node;
};

[[noreturn, gnu::cold, gnu::noinline]] void not_on_node() {
  throw std::logic_error("channel used outside a simulated process on a node");
}

Here here() {
  Kernel* kernel = Kernel::active();
  Process* p = kernel != nullptr ? kernel->current() : nullptr;
  Node* node = p != nullptr ? p->cpu().node() : nullptr;
  if (node == nullptr) [[unlikely]] {
    not_on_node();
  }
  return Here{*kernel, *p, *node};
}

} // namespace

ChanBase::~ChanBase() {
  if (registration_ != nullptr) {
    registration_->channel_ = nullptr;
  }
  if (alt_ != nullptr) {
    alt_->channel_gone(*this);
  }
}

std::string ChanBase::describe() const {
  return external() ? "external channel " + name_ + " (" + output_port_->name() + " -> " +
                          input_port_->name() + ")"
                    : "channel " + name_;
}

void ChanBase::place_on_link(emulator::LinkPort& output_port, emulator::LinkPort& input_port) {
  output_port_ = &output_port;
  input_port_ = &input_port;
  // On a link the CPU no longer copies the message: what was worked out no longer holds.
  output_charge_ = Charge{};
  input_charge_ = Charge{};
}

emulator::Tick ChanBase::charge(Charge& cached, const Node& node, Instruction op,
                                std::size_t bytes) const {
  if (cached.node == node.serial() && cached.bytes == bytes) [[likely]] {
    return cached.time;
  }
  const std::uint64_t cycles = channel_cycles(node, op, external() ? 0 : words(bytes));
  cached = Charge{node.serial(), bytes, node.cycles(cycles)};
  return cached.time;
}

void ChanBase::copy_message(void* destination, const void* source, CopyFn copy) const {
  copy(destination, source);
}

void ChanBase::wait_here(Registration& registration, State state, Process& me, void* data,
                         std::size_t bytes) {
  registration.channel_ = this;
  state_ = state;
  waiter_ = &me;
  data_ = data;
  data_bytes_ = bytes;
  registration_ = &registration;
}

void ChanBase::output(const void* message, std::size_t bytes, CopyFn copy,
                      Registration& registration) {
  auto [kernel, me, node] = here();
  kernel.consume(charge(output_charge_, node, Instruction::out, bytes));
  if (external()) [[unlikely]] {
    output_port_->output(std::span(static_cast<const std::byte*>(message), bytes));
    return;
  }
  if (state_ == State::writer_waiting) {
    throw std::logic_error("channel " + name_ + " has two outputting processes");
  }
  if (state_ == State::reader_waiting) {
    copy_message(data_, message, copy);
    Process* reader = std::exchange(waiter_, nullptr);
    registration_ = nullptr;
    state_ = State::empty;
    kernel.wake(*reader);
    return;
  }
  wait_here(registration, State::writer_waiting, me, const_cast<void*>(message), bytes);
  if (alt_ != nullptr) {
    alt_->guard_ready();
  }
  kernel.block(emulator::WaitInfo{emulator::WaitKind::channel_output, this});
}

void ChanBase::input(void* message, std::size_t bytes, CopyFn copy, Registration& registration) {
  auto [kernel, me, node] = here();
  kernel.consume(charge(input_charge_, node, Instruction::in, bytes));
  if (external()) [[unlikely]] {
    input_port_->input(std::span(static_cast<std::byte*>(message), bytes));
    return;
  }
  if (state_ == State::reader_waiting) {
    throw std::logic_error("channel " + name_ + " has two inputting processes");
  }
  if (state_ == State::writer_waiting) {
    copy_message(message, data_, copy);
    Process* writer = std::exchange(waiter_, nullptr);
    registration_ = nullptr;
    state_ = State::empty;
    kernel.wake(*writer);
    return;
  }
  wait_here(registration, State::reader_waiting, me, message, bytes);
  kernel.block(emulator::WaitInfo{emulator::WaitKind::channel_input, this});
}

bool ChanBase::ready_for_input() const {
  return external() ? input_port_->byte_waiting() : state_ == State::writer_waiting;
}

bool ChanBase::enable(AltState& alt) {
  if (external()) {
    if (input_port_->byte_waiting()) {
      return true;
    }
    input_port_->set_arrival_listener([&alt] { alt.guard_ready(); });
    return false;
  }
  if (state_ == State::writer_waiting) {
    return true;
  }
  alt_ = &alt;
  return false;
}

bool ChanBase::disable(AltState& alt) {
  if (external()) {
    input_port_->set_arrival_listener({});
    return input_port_->byte_waiting();
  }
  if (alt_ == &alt) {
    alt_ = nullptr;
  }
  return state_ == State::writer_waiting;
}

} // namespace marsokhod::occam_port
