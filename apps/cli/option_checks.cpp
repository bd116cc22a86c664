// CLI11 validators over io's checked numbers, so no option reads NaN, infinity or a wrapped
// integer (docs/formats.md, "Command-line options").
#include "cli/option_checks.hpp"

#include <algorithm>
#include <utility>

namespace marsokhod::apps {
namespace detail {

CLI::Validator named_check(std::function<std::string(std::string&)> check,
                           const std::string& description) {
  return {std::move(check), description, kCheckedNumber};
}

} // namespace detail

CLI::Validator real_between(double low, double high) {
  const std::string range = io::range_text(low, high);
  return detail::named_check(
      [low, high, range](std::string& text) -> std::string {
        const std::optional<double> value = io::parse_finite(text);
        if (!value || *value < low || *value > high)
          return fmt::format("'{}' is not a finite number {}", text, range);
        return {};
      },
      fmt::format("{}..{}", low, high));
}

CLI::Validator integer_one_of(std::vector<int> values) {
  const std::string choices = fmt::format("{}", fmt::join(values, ", "));
  const std::string description = fmt::format("{{{}}}", fmt::join(values, ","));
  return detail::named_check(
      [values = std::move(values), choices](std::string& text) -> std::string {
        const std::optional<int> value = io::parse_integer<int>(text);
        if (!value || std::find(values.begin(), values.end(), *value) == values.end())
          return fmt::format("'{}' is not one of {}", text, choices);
        text = fmt::format("{}", *value);
        return {};
      },
      description);
}

} // namespace marsokhod::apps
