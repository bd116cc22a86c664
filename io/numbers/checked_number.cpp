// Text-to-number conversions that refuse what would be garbage: NaN, infinities, junk.
#include "marsokhod/io/numbers/checked_number.hpp"

#include <fmt/format.h>

#include <cmath>

namespace marsokhod::io {

std::optional<double> parse_finite(std::string_view text) {
  if (text.empty() || text.front() == '+')
    return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::string range_text(double low, double high) {
  return fmt::format("between {} and {}", low, high);
}

} // namespace marsokhod::io
