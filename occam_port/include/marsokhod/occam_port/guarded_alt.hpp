// ALT whose guards carry their handlers, so the chosen guard and the input cannot disagree.
#pragma once

#include "marsokhod/occam_port/alt.hpp"
#include "marsokhod/occam_port/chan_ends.hpp"
#include "marsokhod/occam_port/channel.hpp"
#include "marsokhod/occam_port/timer.hpp"

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

namespace marsokhod::occam_port {

/// One ALT alternative: its guard and what runs when the ALT selects it (for an input guard,
/// the input itself and then the handler). Made by on_input, on_after and on_skip; holds the
/// handler by value, so an ALT needs no allocation.
template <typename Action>
class Alternative {
public:
  Alternative(Guard guard, Action action) : guard_(guard), action_(std::move(action)) {}

  const Guard& guard() const { return guard_; }
  /// `condition & alternative`.
  friend Alternative when(bool condition, Alternative alternative) {
    alternative.guard_ = when(condition, alternative.guard_);
    return alternative;
  }
  /// Runs the selected alternative's input (if any) and handler.
  void fire() { action_(); }

private:
  Guard guard_;
  Action action_;
};

/// `in ? x` followed by `handler(x)`: after the ALT selects this guard it inputs from `in`
/// into a fresh T and passes it to the handler, as `c >> x` after the index form would.
template <typename T, typename Handler>
requires std::invocable<Handler&, T&>
auto on_input(ChanIn<T> in, Handler handler) {
  static_assert(std::is_default_constructible_v<T>, "the ALT inputs into a fresh T");
  return Alternative(input(in), [in, handler = std::move(handler)]() mutable {
    T value{};
    in >> value;
    handler(value);
  });
}
template <typename T, typename Handler>
requires std::invocable<Handler&, T&>
auto on_input(Chan<T>& channel, Handler handler) {
  return on_input(channel.in(), std::move(handler));
}

/// `tim ? AFTER t` followed by `handler()`.
template <typename Handler>
requires std::invocable<Handler&>
auto on_after(const Timer& timer, std::int32_t t, Handler handler) {
  return Alternative(after(timer, t), std::move(handler));
}

/// `SKIP` followed by `handler()`: always ready.
template <typename Handler>
requires std::invocable<Handler&>
auto on_skip(Handler handler) {
  return Alternative(skip(), std::move(handler));
}

/// PRI ALT over alternatives that carry their handlers: the same enable, wait and disable
/// sequence (and costs) as `pri_alt({guards...})`, then the selected alternative's input and
/// handler. Returns the index of the alternative that ran.
template <typename... Actions>
requires(sizeof...(Actions) > 0) std::size_t pri_alt(Alternative<Actions>... alternatives) {
  const Guard guards[] = {alternatives.guard()...};
  const std::size_t selected = pri_alt(std::span<const Guard>(guards));
  std::size_t index = 0;
  static_cast<void>(((index++ == selected && (alternatives.fire(), true)) || ...));
  return selected;
}

/// ALT over alternatives that carry their handlers; behaves as PRI ALT (see alt()).
template <typename... Actions>
requires(sizeof...(Actions) > 0) std::size_t alt(Alternative<Actions>... alternatives) {
  return pri_alt(std::move(alternatives)...);
}

} // namespace marsokhod::occam_port
