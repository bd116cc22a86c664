// A channel of byte blocks: a rendezvous in memory, or the link engines between two nodes.

#include "marsokhod/occam_port/navigation/block_channel.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/node/node.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>

namespace marsokhod::occam_port {
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

} // namespace

BlockChannel::BlockChannel(std::string name) : channel_(std::move(name)) {}

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
  emulator::Node::current().execute(emulator::Instruction::out);
  sender_->output(block);
}

void BlockChannel::receive(std::span<std::byte> block) {
  if (!external()) {
    channel_.receive(block);
    return;
  }
  emulator::Node::current().execute(emulator::Instruction::in);
  receiver_->input(block);
}

} // namespace marsokhod::occam_port
