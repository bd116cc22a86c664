// Occam channels: the untyped ChanBase (internal or on a link) and the typed Chan<T>.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/cost_table.hpp"
#include "marsokhod/occam_port/chan_ends.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

namespace marsokhod::emulator {
class LinkPort;
class Node;
} // namespace marsokhod::emulator

namespace marsokhod::occam_port {

class AltState;

/// The untyped core of an occam channel: synchronous, one-to-one, unbuffered. Whichever side
/// arrives first waits; the second copies the message and reschedules the first, as the
/// transputer's in/out microcode does with the channel word. Each side is charged on its node
/// what compiled occam executes: the operand loads (ldlp, ldl, ldc: 4 cycles) and the data-book
/// in/out (2w+19 cycles for w words). A channel placed on a link carries its
/// messages through the link engines instead (an external channel); there in/out cost only
/// their base (19 cycles), since the link's DMA engine moves the bytes.
class ChanBase : public emulator::WaitTarget {
public:
  using CopyFn = void (*)(void* destination, const void* source);

  explicit ChanBase(std::string name) : name_(std::move(name)) {}
  ChanBase(const ChanBase&) = delete;
  ChanBase& operator=(const ChanBase&) = delete;
  ~ChanBase() override;

  const std::string& name() const { return name_; }
  std::string describe() const override;

  bool external() const { return output_port_ != nullptr; }
  /// An outputter is committed and waiting (or, on a link, a byte has arrived): an input
  /// would complete without waiting. What an ALT's disc instruction tests.
  bool ready_for_input() const;

  /// `c ! message`: `bytes` is the message length the transputer would move.
  void output(const void* message, std::size_t bytes, CopyFn copy) {
    Registration registration;
    output(message, bytes, copy, registration);
  }
  /// `c ? message`.
  void input(void* message, std::size_t bytes, CopyFn copy) {
    Registration registration;
    input(message, bytes, copy, registration);
  }

  // ALT support (enbc/disc): ready means an outputter is committed to this channel.
  bool enable(AltState& alt);
  bool disable(AltState& alt);

protected:
  /// The copy of plain values of N bytes; a channel recognises it and copies inline.
  template <std::size_t N>
  static void copy_plain(void* destination, const void* source) {
    std::memcpy(destination, source, N);
  }
  /// Makes this an external channel: the outputting process (on one node) sends through
  /// `output_port`, the inputting process (on the other node) receives from `input_port`;
  /// the two are the ends of one link. Only for messages that are plain bytes.
  void place_on_link(emulator::LinkPort& output_port, emulator::LinkPort& input_port);

private:
  enum class State : unsigned char { empty, reader_waiting, writer_waiting };

  /// Withdraws a waiting side from the channel if its process is killed while it waits, so
  /// the channel never points into a stack that is gone; and forgets the channel if the
  /// channel goes first (one declared outside the processes, destroyed before the kernel).
  class Registration {
  public:
    Registration() = default;
    Registration(const Registration&) = delete;
    Registration& operator=(const Registration&) = delete;
    ~Registration() {
      if (channel_ != nullptr && channel_->registration_ == this)
        channel_->withdraw();
    }

  private:
    friend class ChanBase;
    ChanBase* channel_ = nullptr; ///< set once the side waits
  };

  // The channel operations proper. The registration of a side that waits lives in the
  // caller's frame, so that these can end with a jump into Kernel::block (a tail call)
  // instead of a call: after the switch back the process returns straight into its own code,
  // one return fewer, and each return after a switch is one the processor may mispredict.
  void output(const void* message, std::size_t bytes, CopyFn copy, Registration& registration);
  void input(void* message, std::size_t bytes, CopyFn copy, Registration& registration);
  void wait_here(Registration& registration, State state, emulator::Process& me, void* data,
                 std::size_t bytes);
  void withdraw() {
    state_ = State::empty;
    waiter_ = nullptr;
    data_ = nullptr;
    registration_ = nullptr;
  }
  /// What one side pays per message, worked out once per node and message length.
  struct Charge {
    std::uint64_t node = 0; ///< Node::serial(); 0: nothing worked out yet
    std::size_t bytes = 0;
    emulator::Tick time = 0;
  };
  emulator::Tick charge(Charge& cached, const emulator::Node& node, emulator::Instruction op,
                        std::size_t bytes) const;
  /// Charges through the kernel's slow path, then goes on; out of line, so that the usual path
  /// has no call to come back from.
  [[gnu::noinline]] void output_after_slow_charge(emulator::Tick time, const void* message,
                                                  std::size_t bytes, CopyFn copy,
                                                  Registration& registration);
  [[gnu::noinline]] void input_after_slow_charge(emulator::Tick time, void* message,
                                                 std::size_t bytes, CopyFn copy,
                                                 Registration& registration);
  void output_charged(emulator::Kernel& kernel, emulator::Process& me, const void* message,
                      std::size_t bytes, CopyFn copy, Registration& registration);
  void input_charged(emulator::Kernel& kernel, emulator::Process& me, void* message,
                     std::size_t bytes, CopyFn copy, Registration& registration);
  /// Copies a message of a plain 4- or 8-byte type (see copy_plain) without a call.
  static bool copy_inline(void* destination, const void* source, CopyFn copy);
  /// The second side has the message: the waiting side is released.
  void complete(emulator::Kernel& kernel);
  [[gnu::noinline]] void complete_with_call(emulator::Kernel& kernel, void* destination,
                                            const void* source, CopyFn copy);
  [[gnu::noinline]] void tell_alt_and_block(emulator::Kernel& kernel);
  [[noreturn, gnu::cold, gnu::noinline]] void two_sides(const char* role) const;

  State state_ = State::empty;
  emulator::Process* waiter_ = nullptr;
  void* data_ = nullptr; // the waiting side's message
  std::size_t data_bytes_ = 0;
  AltState* alt_ = nullptr;              // an ALT that enabled this channel and may be waiting
  Registration* registration_ = nullptr; // the waiting side's, on its stack
  emulator::LinkPort* output_port_ = nullptr;
  emulator::LinkPort* input_port_ = nullptr;
  Charge output_charge_;
  Charge input_charge_;
  std::string name_;
};

/// Bytes a value occupies on a channel (the length the transputer's in/out would copy).
template <typename T>
std::size_t message_bytes(const T&) {
  return sizeof(T);
}

/// An occam channel carrying values of T: `c << x` is `c ! x`, `c >> x` is `c ? x`. Hand a
/// process only the end it uses: `c.in()` (a ChanIn<T>) or `c.out()` (a ChanOut<T>); both
/// also convert implicitly from `Chan<T>&`.
template <typename T>
class Chan : public ChanBase {
  static_assert(std::is_copy_assignable_v<T>, "a channel copies its messages");

public:
  explicit Chan(std::string name) : ChanBase(std::move(name)) {}

  Chan& operator<<(const T& value) {
    output(&value, message_bytes(value), copy);
    return *this;
  }
  Chan& operator>>(T& value) {
    input(&value, message_bytes(value), copy);
    return *this;
  }

  /// The input end: can only `>>` and be an ALT guard.
  ChanIn<T> in() { return ChanIn<T>(*this); }
  /// The output end: can only `<<`.
  ChanOut<T> out() { return ChanOut<T>(*this); }

  /// Carries the channel over a link (see ChanBase); the bytes of T travel as they are.
  void place_on_link(emulator::LinkPort& output_port, emulator::LinkPort& input_port) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain bytes can cross a link");
    ChanBase::place_on_link(output_port, input_port);
  }

private:
  static void copy_value(void* destination, const void* source) {
    *static_cast<T*>(destination) = *static_cast<const T*>(source);
  }
  static constexpr CopyFn copy = [] {
    if constexpr (std::is_trivially_copyable_v<T> && (sizeof(T) == 4 || sizeof(T) == 8))
      return &ChanBase::copy_plain<sizeof(T)>;
    else
      return &copy_value;
  }();
};

} // namespace marsokhod::occam_port
