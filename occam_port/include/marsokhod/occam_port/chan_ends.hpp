// Typed channel ends: ChanIn<T> and ChanOut<T>, a process takes only the end it uses.
#pragma once

#include <string>

namespace marsokhod::occam_port {

template <typename T>
class Chan;

namespace detail {
struct EndAccess;
} // namespace detail

/// The input end of a Chan<T>: `in >> x` is `c ? x`, and it can be an ALT guard; it cannot
/// output. A pointer-sized handle, cheap to copy; the channel must outlive it. Made from a
/// channel by `c.in()` or by implicit conversion from `Chan<T>&`.
template <typename T>
class ChanIn {
public:
  using value_type = T;

  ChanIn(Chan<T>& channel) : channel_(&channel) {} // NOLINT(google-explicit-constructor)
  ChanIn(Chan<T>&&) = delete;                      // an end of a temporary channel would dangle

  /// `c ? value`: waits for the outputter, exactly as `Chan<T>::operator>>`.
  const ChanIn& operator>>(T& value) const {
    *channel_ >> value;
    return *this;
  }
  const std::string& name() const { return channel_->name(); }
  /// True when both refer to the same channel.
  friend bool operator==(ChanIn a, ChanIn b) { return a.channel_ == b.channel_; }

private:
  friend struct detail::EndAccess;
  Chan<T>* channel_;
};

/// The output end of a Chan<T>: `out << x` is `c ! x`; it cannot input. A pointer-sized
/// handle, cheap to copy; the channel must outlive it. Made from a channel by `c.out()` or by
/// implicit conversion from `Chan<T>&`.
template <typename T>
class ChanOut {
public:
  using value_type = T;

  ChanOut(Chan<T>& channel) : channel_(&channel) {} // NOLINT(google-explicit-constructor)
  ChanOut(Chan<T>&&) = delete;                      // an end of a temporary channel would dangle

  /// `c ! value`: waits for the inputter, exactly as `Chan<T>::operator<<`.
  const ChanOut& operator<<(const T& value) const {
    *channel_ << value;
    return *this;
  }
  const std::string& name() const { return channel_->name(); }
  /// True when both refer to the same channel.
  friend bool operator==(ChanOut a, ChanOut b) { return a.channel_ == b.channel_; }

private:
  Chan<T>* channel_;
};

namespace detail {
/// What the ALT guards reach through an input end: the channel itself, to enable and disable
/// it and to perform the selected input.
struct EndAccess {
  template <typename T>
  static Chan<T>& channel(ChanIn<T> in) {
    return *in.channel_;
  }
};
} // namespace detail

} // namespace marsokhod::occam_port
