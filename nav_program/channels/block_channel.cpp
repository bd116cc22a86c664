// A channel of byte blocks: a rendezvous in memory, or the link engines between two nodes.

#include "marsokhod/nav_program/channels/block_channel.hpp"

#include "channels/word_sum.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/node/node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

namespace marsokhod::nav_program {
namespace {

struct Block {
  std::byte* data = nullptr;
  const std::byte* source = nullptr;
  std::size_t size = 0;
};

// Runs on the second side of the rendezvous with both descriptors: the receiver's (destination)
// and the sender's (source).
void copy_block(void* destination, const void* source) {
  auto* to = static_cast<Block*>(destination);
  const auto* from = static_cast<const Block*>(source);
  if (to->size != from->size)
    throw std::logic_error(fmt::format("a block channel carried {} bytes into a {}-byte buffer",
                                       from->size, to->size));
  if (from->size > 0)
    std::memcpy(to->data, from->source, from->size);
}

/// The timer half of OutputOrFail.t: at the deadline, resetch on the output's link; gone with
/// the output however it ends (a kill unwinds through it).
class OutputDeadline {
public:
  OutputDeadline(emulator::Kernel& kernel, emulator::LinkPort& port, emulator::Tick after)
      : kernel_(kernel), event_(kernel.schedule_after(after, emulator::event_priority::timer,
                                                      [&port] { port.reset_output(); })) {}
  OutputDeadline(const OutputDeadline&) = delete;
  OutputDeadline& operator=(const OutputDeadline&) = delete;
  ~OutputDeadline() { kernel_.cancel(event_); }

private:
  emulator::Kernel& kernel_;
  emulator::EventId event_;
};

} // namespace

BlockChannel::BlockChannel(std::string name) : channel_(std::move(name)) {}

void BlockChannel::guard(const LinkGuard& guard, TroubleReport report) {
  guard_ = guard;
  report_ = std::move(report);
}

void BlockChannel::place_on_link(emulator::LinkPort& sender, emulator::LinkPort& receiver) {
  sender_ = &sender;
  receiver_ = &receiver;
}

void BlockChannel::Internal::send(std::span<const std::byte> block) {
  Block message{nullptr, block.data(), block.size()};
  output(&message, block.size(), copy_block);
}

void BlockChannel::Internal::receive(std::span<std::byte> block) {
  Block message{block.data(), nullptr, block.size()};
  input(&message, block.size(), copy_block);
}

void BlockChannel::send(std::span<const std::byte> block) {
  bytes_ += block.size();
  ++blocks_;
  if (!external()) {
    channel_.send(block);
    return;
  }
  emulator::Node& node = emulator::Node::current();
  node.execute(emulator::Instruction::out);
  output_guarded(block);
  if (!guard_.checksums)
    return;
  detail::charge_word_sum(node, block.size());
  const std::uint32_t sum = detail::word_sum(block);
  std::array<std::byte, 4> bytes{};
  std::memcpy(bytes.data(), &sum, bytes.size());
  node.execute(emulator::Instruction::out);
  output_guarded(bytes);
}

void BlockChannel::output_guarded(std::span<const std::byte> bytes) {
  if (!guard_.output_timeout) {
    sender_->output(bytes);
    return;
  }
  const OutputDeadline deadline(emulator::Node::current().kernel(), *sender_,
                                *guard_.output_timeout);
  if (!sender_->output(bytes).complete)
    stop_on(*sender_, LinkTrouble::timeout);
}

// occam's STOP once the overswitch has been told: the process waits for ever, until the cycle
// is restarted around it.
void BlockChannel::stop_on(emulator::LinkPort& port, LinkTrouble trouble) {
  if (report_)
    report_(port, trouble);
  emulator::Node::current().kernel().block(emulator::WaitInfo{emulator::WaitKind::other, nullptr});
  throw std::logic_error("channel " + name() + ": a stopped process was woken");
}

void BlockChannel::receive(std::span<std::byte> block) {
  if (!external()) {
    channel_.receive(block);
    return;
  }
  emulator::Node& node = emulator::Node::current();
  node.execute(emulator::Instruction::in);
  receiver_->input(block);
  if (!guard_.checksums)
    return;
  std::array<std::byte, 4> bytes{};
  node.execute(emulator::Instruction::in);
  receiver_->input(bytes);
  detail::charge_word_sum(node, block.size());
  std::uint32_t sum = 0;
  std::memcpy(&sum, bytes.data(), bytes.size());
  if (sum != detail::word_sum(block))
    stop_on(*receiver_, LinkTrouble::checksum);
}

} // namespace marsokhod::nav_program
