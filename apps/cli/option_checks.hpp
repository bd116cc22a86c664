// The one way the command line checks a numeric option: finite, in a closed range, no wrap.
#pragma once

#include "marsokhod/io/numbers/checked_number.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace marsokhod::apps {

/// The name every check of this module carries, so that a test can tell that an option has one
/// (CLI::Option::get_validator(kCheckedNumber)).
inline constexpr const char* kCheckedNumber = "checked-number";

/// A finite decimal number between `low` and `high`, both included: "nan", "inf", "1e309",
/// "0x10", "1x", "" and values outside are refused with a message quoting the value (CLI11
/// puts the option's name before it, and the command line exits 2).
CLI::Validator real_between(double low, double high);

namespace detail {
/// A validator named kCheckedNumber that runs `check` and shows `description` in --help.
CLI::Validator named_check(std::function<std::string(std::string&)> check,
                           const std::string& description);
} // namespace detail

/// A decimal integer between `low` and `high`, both included, read without wrap ("-1" is not
/// an unsigned, "4294967296" not an int) or junk ("1.5", "0x10", "1e3", "+1"). The text is
/// rewritten in canonical decimal, so that CLI11's own conversion (which would read "010" as
/// octal) gives exactly the value that was checked: attach it with Option::transform, which
/// (unlike Option::check) keeps the rewrite.
template <std::integral Int>
CLI::Validator integer_between(Int low, Int high) {
  const std::string range = fmt::format("between {} and {}", low, high);
  return detail::named_check(
      [low, high, range](std::string& text) -> std::string {
        const std::optional<Int> value = io::parse_integer<Int>(text);
        if (!value || *value < low || *value > high)
          return fmt::format("'{}' is not a whole number {}", text, range);
        text = fmt::format("{}", *value);
        return {};
      },
      fmt::format("{}..{}", low, high));
}

/// A decimal integer that is one of `values` (e.g. the image sides 128 and 256); attach it with
/// Option::transform, as integer_between.
CLI::Validator integer_one_of(std::vector<int> values);

/// "A..B", two finite decimals with low <= A <= B <= high (a band of distances, say); nothing
/// when the text is not one.
std::optional<std::pair<double, double>> real_band(const std::string& text, double low,
                                                   double high);

/// The items of a comma-separated list, empty ones included ("64,,128" has three).
std::vector<std::string> comma_items(const std::string& text);

/// A comma-separated list of at most `max_items` decimal integers, each between `low` and
/// `high`, as integer_between reads one; an empty item ("64,,128", "64,") is refused, where
/// CLI11's own splitting would silently drop it. Attach it with Option::check to a std::string
/// option and read the checked text with whole_numbers().
CLI::Validator whole_number_list(std::uint64_t low, std::uint64_t high, std::size_t max_items);

/// The numbers of a list whole_number_list accepted.
std::vector<std::uint64_t> whole_numbers(const std::string& text);

} // namespace marsokhod::apps
