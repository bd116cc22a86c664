// BlockChannel: a channel of the navigation program carrying blocks of bytes, in memory or
// over a link.
#pragma once

#include "marsokhod/nav_program/channels/link_guard.hpp"
#include "marsokhod/occam_port/channel.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace marsokhod::emulator {
class LinkPort;
} // namespace marsokhod::emulator

namespace marsokhod::nav_program {

/// One channel between two processes of the navigation program, carrying blocks of bytes as an
/// occam channel of counted arrays does (`CHAN OF [n]BYTE`): synchronous, one sender, one
/// receiver, each block received into a buffer of the length the protocol says. Between
/// processes of one node it is a channel in memory, charged as the transputer's in/out
/// (2w + 19 cycles for w words, each side); placed on a link, the link's DMA engines move the
/// bytes and each side pays only the instruction's base. Counts the bytes it carried.
class BlockChannel {
public:
  explicit BlockChannel(std::string name);

  const std::string& name() const { return channel_.name(); }
  /// Carries the channel over the link whose ends are `sender` (the sending node's port) and
  /// `receiver` (the receiving node's).
  void place_on_link(emulator::LinkPort& sender, emulator::LinkPort& receiver);
  bool external() const { return sender_ != nullptr; }

  /// Called in a process with the port a guarded message failed on and what went wrong; the
  /// process stops once it returns.
  using TroubleReport = std::function<void(emulator::LinkPort& port, LinkTrouble trouble)>;
  /// Guards the channel's messages on its link as `guard` says (in memory it changes nothing).
  void guard(const LinkGuard& guard, TroubleReport report);

  /// `c ! block`: returns once the receiver has the bytes.
  void send(std::span<const std::byte> block);
  /// `c ? block`: the block must have the sender's length (std::logic_error otherwise: the two
  /// sides of the protocol disagree).
  void receive(std::span<std::byte> block);

  std::uint64_t bytes_carried() const { return bytes_; }
  std::uint64_t blocks_carried() const { return blocks_; }

private:
  /// An internal channel whose messages are block descriptors: the copy moves the bytes.
  class Internal : public occam_port::ChanBase {
  public:
    using occam_port::ChanBase::ChanBase;
    void send(std::span<const std::byte> block);
    void receive(std::span<std::byte> block);
  };

  Internal channel_;
  /// Sends on the link, giving the message up at the guard's timeout.
  void output_guarded(std::span<const std::byte> bytes);
  [[noreturn]] void stop_on(emulator::LinkPort& port, LinkTrouble trouble);

  emulator::LinkPort* sender_ = nullptr;
  emulator::LinkPort* receiver_ = nullptr;
  LinkGuard guard_;
  TroubleReport report_;
  std::uint64_t bytes_ = 0;
  std::uint64_t blocks_ = 0;
};

} // namespace marsokhod::nav_program
