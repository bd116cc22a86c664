// Channel communication: the in/out rendezvous, its charges, and external channels on links.

#include "marsokhod/occam_port/channel.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/node/node.hpp"
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
  if (node == nullptr) [[unlikely]]
    not_on_node();
  return Here{*kernel, *p, *node};
}

} // namespace

ChanBase::~ChanBase() {
  if (registration_ != nullptr)
    registration_->channel_ = nullptr;
  if (alt_ != nullptr)
    alt_->channel_gone(*this);
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
  if (cached.node == node.serial() && cached.bytes == bytes) [[likely]]
    return cached.time;
  const std::uint64_t cycles = channel_cycles(node, op, external() ? 0 : words(bytes));
  cached = Charge{node.serial(), bytes, node.cycles(cycles)};
  return cached.time;
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

// The two operations below keep every call on their usual paths a tail call (into
// Kernel::block, the link port, or a cold helper): with no call to come back from they need no
// saved registers, no stack frame, and they copy small plain messages inline.

void ChanBase::output(const void* message, std::size_t bytes, CopyFn copy,
                      Registration& registration) {
  auto [kernel, me, node] = here();
  const emulator::Tick time = charge(output_charge_, node, Instruction::out, bytes);
  if (!kernel.consume_quickly(time)) [[unlikely]]
    return output_after_slow_charge(time, message, bytes, copy, registration);
  output_charged(kernel, me, message, bytes, copy, registration);
}

void ChanBase::output_after_slow_charge(emulator::Tick time, const void* message, std::size_t bytes,
                                        CopyFn copy, Registration& registration) {
  Kernel& kernel = *Kernel::active();
  kernel.consume(time);
  output_charged(kernel, *kernel.current(), message, bytes, copy, registration);
}

inline void ChanBase::output_charged(Kernel& kernel, Process& me, const void* message,
                                     std::size_t bytes, CopyFn copy, Registration& registration) {
  if (external()) [[unlikely]] {
    output_port_->output(std::span(static_cast<const std::byte*>(message), bytes));
    return;
  }
  if (state_ == State::writer_waiting) [[unlikely]]
    two_sides("outputting");
  if (state_ == State::reader_waiting) {
    if (!copy_inline(data_, message, copy)) [[unlikely]]
      return complete_with_call(kernel, data_, message, copy);
    complete(kernel);
    return;
  }
  wait_here(registration, State::writer_waiting, me, const_cast<void*>(message), bytes);
  if (alt_ != nullptr) [[unlikely]]
    return tell_alt_and_block(kernel);
  kernel.block(emulator::WaitInfo{emulator::WaitKind::channel_output, this});
}

void ChanBase::input(void* message, std::size_t bytes, CopyFn copy, Registration& registration) {
  auto [kernel, me, node] = here();
  const emulator::Tick time = charge(input_charge_, node, Instruction::in, bytes);
  if (!kernel.consume_quickly(time)) [[unlikely]]
    return input_after_slow_charge(time, message, bytes, copy, registration);
  input_charged(kernel, me, message, bytes, copy, registration);
}

void ChanBase::input_after_slow_charge(emulator::Tick time, void* message, std::size_t bytes,
                                       CopyFn copy, Registration& registration) {
  Kernel& kernel = *Kernel::active();
  kernel.consume(time);
  input_charged(kernel, *kernel.current(), message, bytes, copy, registration);
}

inline void ChanBase::input_charged(Kernel& kernel, Process& me, void* message, std::size_t bytes,
                                    CopyFn copy, Registration& registration) {
  if (external()) [[unlikely]] {
    input_port_->input(std::span(static_cast<std::byte*>(message), bytes));
    return;
  }
  if (state_ == State::reader_waiting) [[unlikely]]
    two_sides("inputting");
  if (state_ == State::writer_waiting) {
    if (!copy_inline(message, data_, copy)) [[unlikely]]
      return complete_with_call(kernel, message, data_, copy);
    complete(kernel);
    return;
  }
  wait_here(registration, State::reader_waiting, me, message, bytes);
  kernel.block(emulator::WaitInfo{emulator::WaitKind::channel_input, this});
}

bool ChanBase::copy_inline(void* destination, const void* source, CopyFn copy) {
  if (copy == &copy_plain<4>) {
    std::memcpy(destination, source, 4);
    return true;
  }
  if (copy == &copy_plain<8>) {
    std::memcpy(destination, source, 8);
    return true;
  }
  return false;
}

void ChanBase::complete(Kernel& kernel) {
  Process* waiter = std::exchange(waiter_, nullptr);
  registration_ = nullptr;
  state_ = State::empty;
  kernel.wake(*waiter);
}

void ChanBase::complete_with_call(Kernel& kernel, void* destination, const void* source,
                                  CopyFn copy) {
  // Copied before the waiting side is released: a copy that throws leaves it waiting.
  copy(destination, source);
  complete(kernel);
}

void ChanBase::tell_alt_and_block(Kernel& kernel) {
  alt_->guard_ready();
  kernel.block(emulator::WaitInfo{emulator::WaitKind::channel_output, this});
}

void ChanBase::two_sides(const char* role) const {
  throw std::logic_error("channel " + name_ + " has two " + role + " processes");
}

bool ChanBase::ready_for_input() const {
  return external() ? input_port_->byte_waiting() : state_ == State::writer_waiting;
}

bool ChanBase::enable(AltState& alt) {
  if (external()) {
    if (input_port_->byte_waiting())
      return true;
    input_port_->set_arrival_listener([&alt] { alt.guard_ready(); });
    return false;
  }
  if (state_ == State::writer_waiting)
    return true;
  alt_ = &alt;
  return false;
}

bool ChanBase::disable(AltState& alt) {
  if (external()) {
    input_port_->set_arrival_listener({});
    return input_port_->byte_waiting();
  }
  if (alt_ == &alt)
    alt_ = nullptr;
  return state_ == State::writer_waiting;
}

} // namespace marsokhod::occam_port
