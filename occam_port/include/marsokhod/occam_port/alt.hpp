// ALT and PRI ALT, index form: guards and the transputer's enable/wait/disable sequence.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/occam_port/channel.hpp"
#include "marsokhod/occam_port/timer.hpp"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::occam_port {

/// One ALT alternative's guard: an input from a channel, a timeout, or SKIP, each with an
/// optional boolean precondition (`cond & c ? x`).
struct Guard {
  enum class Kind : unsigned char { channel, timer, skip };
  Kind kind = Kind::skip;
  bool precondition = true;
  ChanBase* channel = nullptr;
  std::int32_t after = 0; ///< timer guards: ready once the clock is AFTER this value
};

/// `c ? ...` as a guard; after the ALT selects it, perform the input yourself (`c >> x`).
inline Guard input(ChanBase& channel) {
  return Guard{Guard::Kind::channel, true, &channel, 0};
}
/// `c ? ...` as a guard on an input end; perform the input on the same end (`in >> x`).
template <typename T>
Guard input(ChanIn<T> in) {
  return input(static_cast<ChanBase&>(detail::EndAccess::channel(in)));
}
/// `tim ? AFTER t` as a guard.
inline Guard after(const Timer&, std::int32_t t) {
  return Guard{Guard::Kind::timer, true, nullptr, t};
}
/// `SKIP` as a guard: always ready.
inline Guard skip() {
  return Guard{};
}
/// `condition & guard`.
inline Guard when(bool condition, Guard guard) {
  guard.precondition = guard.precondition && condition;
  return guard;
}

/// The state of one ALT while it runs, on the ALTing process's stack; channels and link ports
/// that were enabled call guard_ready() when an outputter commits to them.
class AltState : public emulator::WaitTarget {
public:
  AltState(emulator::Kernel& kernel, emulator::Process& process, std::span<const Guard> guards);
  AltState(const AltState&) = delete;
  AltState& operator=(const AltState&) = delete;
  ~AltState() override;

  /// An enabled guard became ready: wake the ALT if it waits.
  void guard_ready();
  /// An enabled channel is being destroyed (while its ALT's process is being killed).
  void channel_gone(const ChanBase& channel) { gone_.push_back(&channel); }
  std::string describe() const override;

  /// Runs enable, wait and disable; returns the index of the selected guard.
  std::size_t run();

private:
  bool enable_all();
  std::size_t disable_all();
  void wait();

  emulator::Kernel& kernel_;
  emulator::Process& process_;
  std::span<const Guard> guards_;
  std::size_t enabled_ = 0; ///< guards [0, enabled_) have been enabled
  bool ready_ = false;
  bool waiting_ = false;
  bool has_timer_ = false;
  std::int32_t earliest_ = 0;
  std::vector<const ChanBase*> gone_;
};

/// PRI ALT: enables the guards in order, waits until one is ready, then disables them in
/// order; the first ready guard in that order wins. Returns its index. With no enabled guard
/// it waits forever, like STOP.
std::size_t pri_alt(std::span<const Guard> guards);
inline std::size_t pri_alt(std::initializer_list<Guard> guards) {
  return pri_alt(std::span<const Guard>(guards.begin(), guards.size()));
}

/// ALT: occam leaves the choice open; the transputer's compiled ALT takes the first ready
/// guard in the order the disable instructions run, which is textual order here, so it
/// behaves as PRI ALT.
inline std::size_t alt(std::span<const Guard> guards) {
  return pri_alt(guards);
}
inline std::size_t alt(std::initializer_list<Guard> guards) {
  return pri_alt(guards);
}

} // namespace marsokhod::occam_port
