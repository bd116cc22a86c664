// The handshake timing of a link at a given speed: data and acknowledge packets.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

namespace marsokhod::emulator {

/// The handshake timing of one link at one speed, in picoseconds.
struct LinkTiming {
  Tick bit = 0;
  Tick data_packet = 0;
  Tick ack_packet = 0;
  Tick ack_delay = 0;
  Tick ack_turnaround = 0;
  Tick gap = 0;

  /// Bit-time parameters times the bit time of `mbps` (10 Mbit/s: 100'000 ps per bit).
  static LinkTiming from(const LinkTimingSpec& spec, int mbps);
};

/// What the framing machine did in one step.
struct LinkStep {
  enum class Kind : std::uint8_t {
    none,
    data_end,  ///< a data packet finished arriving at `end`'s peer
    ack_end,   ///< an acknowledge finished arriving at `end` (the data sender)
    ack_start, ///< `end` started an acknowledge
    data_start ///< `end` started a data packet
  };
  Kind kind = Kind::none;
  int end = 0;
  Tick time = 0;
  /// data_end: the receiver had an input waiting and took the byte (otherwise the byte waits
  /// unacknowledged in the receiver's one-byte buffer, or was lost on a dead link).
  /// ack_end: the sender was waiting for it (it was not reset meanwhile) and it arrived.
  bool accepted = false;
  /// data_start, ack_start: the packet will not arrive (its wire is dead, or it is an
  /// acknowledge to be lost).
  bool lost = false;
};

/// The INMOS link protocol between two ends (0 and 1) as a pure state machine of byte counts
/// and times. Each end sends 11-bit data packets on its own wire and acknowledges its peer's
/// packets with 2-bit packets on that same wire, so acknowledges share the wire with data.
/// A receiver with an input waiting acknowledges `ack_delay` after the start bit (or as soon
/// as its wire is free); a sender starts its next byte only after the acknowledge of the
/// previous one has arrived plus `ack_turnaround`. Throughput follows from these rules alone.
class LinkFraming {
public:
  explicit LinkFraming(const LinkTiming& timing);

  const LinkTiming& timing() const { return timing_; }
  Tick now() const { return now_; }

  /// `end` has `bytes` more to send (an output instruction started at `now`).
  void offer_output(int end, Tick now, std::uint64_t bytes);
  /// `end` wants `bytes` more (an input instruction started at `now`). Returns true when a
  /// byte was already waiting in its buffer: it is taken at once (and acknowledged).
  bool offer_input(int end, Tick now, std::uint64_t bytes);
  /// A byte waits unacknowledged in `end`'s receive buffer (an ALT guard on the link is ready).
  bool byte_waiting(int end) const { return ends_[end].holding; }
  /// Bytes `end` still has to send (including one awaiting its acknowledge).
  std::uint64_t output_left(int end) const;
  std::uint64_t input_left(int end) const { return ends_[end].accept_budget; }

  /// Stops everything `end` does and forgets its state (power-off, link reset). Packets on the
  /// wire from the other end are lost; that end's sender waits for an acknowledge forever.
  void reset_end(int end, Tick now, bool alive);
  /// Forgets the bytes `end` has not started sending yet (its process gave up the output).
  void withdraw_output(int end) {
    ends_[end].queued = 0;
    ++generation_;
  }
  /// Forgets how many bytes `end` still wanted (its process gave up the input).
  void withdraw_input(int end) {
    ends_[end].accept_budget = 0;
    ++generation_;
  }
  bool alive(int end) const { return ends_[end].alive; }

  /// Kills or mends the wire `end` drives, which carries its data packets and its
  /// acknowledges of the peer's data. A packet's fate is settled by its start bit: one that
  /// starts on a dead wire is lost whole, one already on the wire when it dies still arrives
  /// (the receiver commits to a byte, and acknowledges it, early in the packet).
  void set_wire_dead(int end, bool dead) {
    wire_dead_[end] = dead;
    ++generation_;
  }
  bool wire_dead(int end) const { return wire_dead_[end]; }
  /// A broken cable: both wires dead (packets are sent but never arrive); mending it mends both.
  void set_broken(bool broken) {
    wire_dead_ = {broken, broken};
    ++generation_;
  }
  bool broken() const { return wire_dead_[0] && wire_dead_[1]; }
  /// The next acknowledge `end` starts is lost on its wire (each call loses one more).
  void lose_acknowledge(int end) {
    ++acks_to_lose_[end];
    ++generation_;
  }

  /// `resetch` on `end`'s output channel: forgets the bytes not yet sent and the acknowledge
  /// awaited, so a new output may start. A data packet already on the wire still arrives;
  /// acknowledges carry no byte number, so a late one counts for the next byte sent.
  void reset_output(int end, Tick now);
  /// `resetch` on `end`'s input channel: forgets the bytes still wanted, the byte waiting in
  /// the buffer and an acknowledge not yet started (the peer's sender then waits for it
  /// forever). A byte on the wire that was already taken is dropped when it arrives.
  void reset_input(int end, Tick now);

  /// Time of the next step, kNever when nothing can happen without new offers.
  Tick next_time() const;
  /// Performs the earliest step (time order; at one instant packet ends, then acknowledges,
  /// then data, end 0 before end 1). Returns Kind::none when nothing is pending.
  LinkStep step();

  /// Called just after `sender` started a data packet. A one-way stream repeats itself byte
  /// after byte: when the machine stands now where it stood at that end's previous data start,
  /// its times shifted by one byte period and one byte fewer to send and to take (with nothing
  /// offered, withdrawn, reset or faulted in between, and no wire dead or acknowledge still to
  /// be lost), returns that period; otherwise nothing.
  /// Either way this data start becomes the one the next call compares with.
  std::optional<Tick> stream_period(int sender);
  /// Jumps `bytes` byte periods of `sender`'s stream at once, as that many data packets,
  /// acknowledges and next data starts would: every pending time moves on `bytes * period`.
  /// Only after stream_period() gave `period`, and only for fewer bytes than are left to send
  /// and to take.
  void skip_stream(int sender, std::uint64_t bytes, Tick period);
  /// Bytes a skip_stream() may jump for `sender`: one fewer than it has left to send and than
  /// its peer has left to take, so that the last byte of either is stepped.
  std::uint64_t skippable_bytes(int sender) const;

private:
  struct End {
    bool alive = true;
    // Sender side: bytes not yet started, and the state of the byte on the wire.
    std::uint64_t queued = 0;
    bool awaiting_ack = false;
    Tick next_data_allowed = 0;
    // The wire this end drives: data packets out, acknowledges of the peer's data.
    Tick wire_free = 0;
    Tick data_end = kNever;     ///< end of the data packet on this end's wire
    bool data_accepted = false; ///< its receiver had taken it at the start bit
    bool data_lost = false;     ///< it started on a dead wire
    bool data_dropped = false;  ///< its receiver took it, then was reset
    bool ack_lost = false;      ///< the acknowledge on this wire will not arrive
    Tick data_start = 0;
    Tick ack_end = kNever; ///< end of the acknowledge on this end's wire
    // Receiver side.
    std::uint64_t accept_budget = 0;
    bool holding = false; ///< one unacknowledged byte in the receive buffer
    bool ack_owed = false;
    Tick ack_ready = kNever; ///< earliest start of the owed acknowledge

    bool operator==(const End&) const = default;
  };

  /// The machine as seen from a data start of one end, times relative to it (a past time
  /// that only bounds a later one from below counts as now).
  struct Phase {
    std::array<End, 2> ends{};
    std::uint64_t generation = 0;
    Tick at = 0;
    bool valid = false;
  };
  Phase phase_at_now() const;
  Tick data_start_time(int end) const;
  Tick ack_start_time(int end) const;
  void accept_in_flight(int receiver);
  /// start_data() and start_ack() return whether the packet will be lost.
  bool start_data(int sender, Tick at);
  void end_data(int sender, LinkStep& step);
  bool start_ack(int receiver, Tick at);
  void end_ack(int receiver, LinkStep& step);

  LinkTiming timing_;
  std::array<End, 2> ends_{};
  Tick now_ = 0;
  /// By the end that drives the wire.
  std::array<bool, 2> wire_dead_{};
  std::array<std::uint32_t, 2> acks_to_lose_{};
  /// Counts the offers, withdrawals, resets and faults: a stream repeats itself only between two.
  std::uint64_t generation_ = 0;
  std::array<Phase, 2> last_data_start_{};
};

// Asked for after every packet step: inline.

inline Tick LinkFraming::ack_start_time(int end) const {
  const End& self = ends_[end];
  if (!self.ack_owed || !self.alive)
    return kNever;
  return std::max({now_, self.wire_free, self.ack_ready});
}

inline Tick LinkFraming::data_start_time(int end) const {
  const End& self = ends_[end];
  if (!self.alive || self.queued == 0 || self.awaiting_ack)
    return kNever;
  const Tick at = std::max({now_, self.wire_free, self.next_data_allowed});
  // An owed acknowledge that can go no later than the data goes first.
  if (ack_start_time(end) <= at)
    return kNever;
  return at;
}

inline Tick LinkFraming::next_time() const {
  Tick next = kNever;
  for (int end = 0; end < 2; ++end)
    next = std::min(
        {next, ends_[end].data_end, ends_[end].ack_end, ack_start_time(end), data_start_time(end)});
  return next;
}

} // namespace marsokhod::emulator
