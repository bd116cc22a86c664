// A link output that several processes of one node take turns at.
#pragma once

#include "marsokhod/emulator/links/link.hpp"

#include <cstddef>
#include <deque>
#include <functional>
#include <initializer_list>
#include <span>
#include <string>

namespace marsokhod::emulator {

/// One link's output shared by processes of one node, each whole message in its turn, in the
/// order they asked: the effect of an occam multiplexer process in front of the link (an ALT
/// over the senders' channels, then the output). The few cycles the multiplexer spends per
/// message are not charged. A process killed while waiting or sending gives its turn up.
class SharedOutput : public WaitTarget {
public:
  explicit SharedOutput(LinkPort& port) : port_(&port) {}
  SharedOutput(const SharedOutput&) = delete;
  SharedOutput& operator=(const SharedOutput&) = delete;

  LinkPort& port() const { return *port_; }
  /// Waits for the turn, then outputs `message` on the port. Only from a process.
  void output(std::span<const std::byte> message) { output({message}); }
  /// Outputs `parts` one after the other in one turn (a header and its payload, which nothing
  /// may come between); `before_each` (may be empty) runs before each part, to charge its
  /// `out` instruction.
  void output(std::initializer_list<std::span<const std::byte>> parts,
              const std::function<void()>& before_each = {});
  /// Processes waiting for their turn.
  std::size_t waiting() const { return waiting_.size(); }

  std::string describe() const override;

private:
  class Turn;
  LinkPort* port_;
  Process* holder_ = nullptr;
  std::deque<Process*> waiting_;
};

} // namespace marsokhod::emulator
