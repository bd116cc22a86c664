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

std::optional<std::pair<double, double>> real_band(const std::string& text, double low,
                                                   double high) {
  const std::size_t dots = text.find("..");
  if (dots == std::string::npos)
    return std::nullopt;
  const std::optional<double> near = io::parse_finite(text.substr(0, dots));
  const std::optional<double> far = io::parse_finite(text.substr(dots + 2));
  if (!near || !far || *near < low || *far > high || *far < *near)
    return std::nullopt;
  return std::pair{*near, *far};
}

std::vector<std::string> comma_items(const std::string& text) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = text.find(',', begin);
    items.push_back(text.substr(begin, comma == std::string::npos ? comma : comma - begin));
    if (comma == std::string::npos)
      return items;
    begin = comma + 1;
  }
}

CLI::Validator whole_number_list(std::uint64_t low, std::uint64_t high, std::size_t max_items) {
  return detail::named_check(
      [low, high, max_items](std::string& text) -> std::string {
        const std::vector<std::string> items = comma_items(text);
        if (items.size() > max_items)
          return fmt::format("'{}' lists {} values, at most {} are taken", text, items.size(),
                             max_items);
        for (std::size_t i = 0; i < items.size(); ++i) {
          if (items[i].empty())
            return fmt::format("'{}': item {} is empty (write whole numbers separated by single "
                               "commas, e.g. 64,128,256)",
                               text, i + 1);
          const std::optional<std::uint64_t> value = io::parse_integer<std::uint64_t>(items[i]);
          if (!value || *value < low || *value > high)
            return fmt::format("'{}': '{}' is not a whole number between {} and {}", text, items[i],
                               low, high);
        }
        return {};
      },
      fmt::format("LIST of {}..{}", low, high));
}

std::vector<std::uint64_t> whole_numbers(const std::string& text) {
  std::vector<std::uint64_t> numbers;
  for (const std::string& item : comma_items(text))
    numbers.push_back(io::parse_integer<std::uint64_t>(item).value_or(0));
  return numbers;
}

} // namespace marsokhod::apps
