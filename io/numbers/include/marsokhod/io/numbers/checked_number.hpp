// Reading a number from text, or narrowing one, with no wrap, no NaN and no trailing junk.
#pragma once

#include <charconv>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace marsokhod::io {

/// The whole of `text` as a finite double ("1e3", "-0.5"); nothing for "nan", "inf", "1e999",
/// "", " 1" or "1x".
std::optional<double> parse_finite(std::string_view text);

/// The whole of `text` as an Int, in decimal; nothing when it does not fit Int (no wrap: "-1"
/// is not an unsigned, "4294967296" is not an int32) or holds anything else.
template <std::integral Int>
std::optional<Int> parse_integer(std::string_view text) {
  if (text.empty() || text.front() == '+')
    return std::nullopt;
  Int value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    return std::nullopt;
  return value;
}

/// `value` as a To when it is representable exactly, nothing otherwise.
template <std::integral To, std::integral From>
std::optional<To> narrow(From value) {
  if (!std::in_range<To>(value))
    return std::nullopt;
  return static_cast<To>(value);
}

/// `value` as a To when it is an integer within To's range; nothing for NaN, fractions or
/// magnitudes that would wrap or be undefined on conversion.
template <std::integral To>
std::optional<To> integer_from_real(double value) {
  // Both bounds are exact powers of two as doubles, so the comparison itself cannot round in.
  constexpr double kLow = static_cast<double>(std::numeric_limits<To>::min());
  constexpr double kHighExclusive =
      2.0 * (static_cast<double>(std::numeric_limits<To>::max() / 2) + 1.0);
  if (!(value >= kLow && value < kHighExclusive))
    return std::nullopt;
  const To whole = static_cast<To>(value);
  if (static_cast<double>(whole) != value)
    return std::nullopt;
  return whole;
}

/// "between -45 and 45": a closed range as messages state it.
std::string range_text(double low, double high);

} // namespace marsokhod::io
