// T805 links: an output and an input DMA engine at each end of a wire.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link_framing.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::emulator {

class Link;

/// How a blocking transfer on a link port ended.
struct LinkTransferResult {
  /// False when a reset of the port cut the transfer short.
  bool complete = true;
  /// Bytes acknowledged (output) or stored (input) by then: the whole message when complete.
  std::size_t bytes = 0;

  explicit operator bool() const { return complete; }
};

/// One end of a link as its node sees it: an output and an input DMA engine that run on
/// their own while the CPU computes. Occam's external channels use it: a process outputs or
/// inputs a whole message and blocks until the engine is done; an ALT asks whether a byte is
/// waiting and is told when one arrives.
class LinkPort : public WaitTarget {
public:
  /// Called when a transfer has finished (from a kernel event; must not block).
  using Done = std::function<void()>;

  /// "module0.link2".
  const std::string& name() const { return name_; }
  Link& link() const { return *link_; }
  int end() const { return end_; }

  /// Sends `message`: returns once its last byte is acknowledged, or as soon as a reset cuts
  /// it short. Only from a process.
  LinkTransferResult output(std::span<const std::byte> message);
  /// Fills `buffer` from the link: returns once its last byte has arrived, or as soon as a
  /// reset cuts it short. Only from a process.
  LinkTransferResult input(std::span<std::byte> buffer);

  /// Starts sending without blocking; `done` runs after the last acknowledge. The bytes must
  /// stay valid until then. One output at a time.
  void start_output(std::span<const std::byte> message, Done done);
  /// Starts receiving without blocking; `done` runs after the last byte (possibly before this
  /// returns, when the message is one byte that was already waiting). One input at a time.
  void start_input(std::span<std::byte> buffer, Done done);
  bool output_busy() const { return output_.active; }
  bool input_busy() const { return input_.active; }
  /// Bytes this end has sent and had acknowledged, over all its outputs.
  std::uint64_t bytes_sent() const { return bytes_sent_; }
  /// Simulated time this end's output engine spent on messages, from each output's start to
  /// its last acknowledge (or until it was given up).
  Tick output_busy_time() const { return output_busy_; }

  /// `resetch` on this end's output channel, as occam's OutputOrFail and Reinitialise use it
  /// to end a hung link output: the engine forgets its transfer, and a process blocked in
  /// output() resumes at once, told the transfer was cut short and how many bytes were
  /// acknowledged. A start_output() transfer is forgotten without calling its `done`. The
  /// peer is not reset: its input keeps waiting and would take the next message's bytes, so
  /// both ends are reset before the link is used again. Returns whether an output was cut.
  bool reset_output();
  /// `resetch` on this end's input channel: as reset_output(), for the input engine (a byte
  /// waiting unacknowledged is forgotten too, so the peer's output waits until it is reset).
  bool reset_input();
  /// `resetch` on both channels of this end. Returns whether a transfer was cut.
  bool reset();

  /// A byte has arrived that no input has taken yet (an ALT guard on this link is ready).
  bool byte_waiting() const;
  /// `listener` runs when a byte arrives with no input waiting for it (ALT enable); an empty
  /// function removes it (ALT disable).
  void set_arrival_listener(std::function<void()> listener);

  std::string describe() const override;

private:
  friend class Link;
  struct Transfer {
    bool active = false;
    std::span<std::byte> in;
    std::span<const std::byte> out;
    std::size_t started = 0; ///< bytes put on the wire (output)
    std::size_t done = 0;    ///< bytes acknowledged (output) or stored (input)
    std::uint64_t flow = 0;  ///< trace arrow from this output to the peer's input track
    Done on_done;
    /// Where a process blocked in output() or input() is told that a reset cut it short.
    LinkTransferResult* report = nullptr;
  };

  void begin_output(std::span<const std::byte> message, Done done, LinkTransferResult* report);
  void begin_input(std::span<std::byte> buffer, Done done, LinkTransferResult* report);
  void finish(Transfer& transfer, TrackId track);
  /// Ends a transfer a reset forgot: its process, if one is blocked on it, resumes.
  void cut_short(Transfer& transfer, TrackId track);
  void abandon_output();
  /// Adds the output in progress (its acknowledged bytes, its time so far) to the totals.
  void count_output();
  void abandon_input();

  std::string name_;
  Link* link_ = nullptr;
  int end_ = 0;
  Transfer output_;
  Transfer input_;
  std::byte held_{};
  Tick output_since_ = 0;
  std::uint64_t bytes_sent_ = 0;
  Tick output_busy_ = 0;
  std::function<void()> arrival_listener_;
  TrackId out_track_ = 0;
  TrackId in_track_ = 0;
};

/// A pair of wires between two link ports, driven through the kernel's event queue by the
/// framing machine. Bytes move only between powered ends over a live wire; faults of a wire
/// (dead, a flipped bit, a lost acknowledge) can be injected at any time.
class Link : public EventHandler {
public:
  /// `id` makes trace flow ids unique across links.
  Link(Kernel& kernel, std::string end0, std::string end1, const LinkTiming& timing,
       std::uint32_t id = 0);
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;
  ~Link() override;

  LinkPort& port(int end) { return ports_[end]; }
  const LinkFraming& framing() const { return framing_; }
  Kernel& kernel() const { return *kernel_; }

  /// Power change of the node at `end`: its engines stop and forget their transfers (a
  /// process of that node waiting on them is being killed anyway); powering on resets them.
  /// Setting the state an end already has changes nothing.
  void set_powered(int end, bool powered);
  /// A broken cable: both wires dead (true) or both mended (false).
  void set_broken(bool broken);

  /// Kills (`dead`) or mends the wire end `from_end` drives: nothing it puts on it arrives,
  /// neither its data nor its acknowledges of the peer's data, so the peer's outputs stall
  /// after their first byte. What was lost stays lost (the protocol has no retransmission): a
  /// sender whose acknowledge was lost waits until a reset. A packet's fate is settled by its
  /// start bit (LinkFraming::set_wire_dead).
  void set_wire_dead(int from_end, bool dead);
  /// The `nth_byte`-th data byte (0: the next) that end `from_end` starts sending from now on
  /// arrives with bit `bit` (0..7) inverted: link packets carry no parity, so the receiver
  /// stores it as it comes.
  void flip_data_bit(int from_end, std::uint64_t nth_byte, unsigned bit);
  /// The next acknowledge end `from_end` sends is lost on the wire: the peer's output waits
  /// for it until a reset. Each call loses one more.
  void lose_acknowledge(int from_end);

  void on_event(std::uint64_t tag) override;

private:
  friend class LinkPort;
  void offered();
  void reschedule();
  /// reschedule() for a next step time already worked out.
  void schedule_next(Tick next);
  void handle(const LinkStep& step);
  void jump_stream(int sender);
  void on_data_start(int sender);
  void on_data_end(int sender, bool accepted);
  void on_ack_end(int sender);
  /// Inverts the bits due to be flipped in data byte `byte` of `sender`, now on the wire.
  void apply_flips(int sender, std::uint64_t byte);
  /// Data bytes `sender` may start before the next one with a flip pending.
  std::uint64_t bytes_before_flip(int sender) const;
  void note_lost_acknowledge(int end);
  static void check_end(int end);
  void declare_tracks(TraceSink& sink);
  /// The kernel's sink with this link's tracks declared, or nullptr.
  TraceSink* trace();
  std::uint64_t next_flow_id();

  Kernel* kernel_;
  LinkFraming framing_;
  std::array<LinkPort, 2> ports_;
  std::array<std::byte, 2> on_wire_{};
  /// Flow id of the message whose last byte is on each wire, 0 otherwise.
  std::array<std::uint64_t, 2> last_byte_flow_{};
  /// Data bytes each end has started, over all its outputs: what a flip's byte counts in.
  std::array<std::uint64_t, 2> data_started_{};
  struct BitFlip {
    std::uint64_t byte = 0;
    std::byte mask{};
  };
  std::array<std::vector<BitFlip>, 2> flips_;
  std::uint32_t id_;
  std::uint64_t messages_ = 0;
  bool tracks_declared_ = false;
  /// Expires with the link, so a process unwinding after it knows not to touch its port.
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);
  EventId event_ = 0;
  Tick event_time_ = kNever;
};

} // namespace marsokhod::emulator
