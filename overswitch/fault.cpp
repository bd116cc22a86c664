// The `--inject` grammar: KIND:MODULE@WHEN.

#include "marsokhod/overswitch/fault.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>

namespace marsokhod::overswitch {
namespace {

constexpr emulator::Tick kLongestOffset = 3600 * emulator::kSecond;

constexpr std::array<std::pair<std::string_view, Fault::Kind>, 3> kKinds{
    {{"hang", Fault::Kind::hang}, {"power", Fault::Kind::power_loss}, {"leak", Fault::Kind::leak}}};

constexpr std::array<std::pair<std::string_view, emulator::Tick>, 3> kUnits{
    {{"ms", emulator::kMillisecond}, {"us", emulator::kMicrosecond}, {"s", emulator::kSecond}}};

[[noreturn]] void fail(std::string_view spec, const std::string& problem) {
  throw FaultSpecError(fmt::format("--inject '{}': {}", spec, problem));
}

Fault::Kind kind_of(std::string_view spec, std::string_view text) {
  for (const auto& [name, kind] : kKinds)
    if (text == name)
      return kind;
  fail(spec, fmt::format("unknown fault kind '{}' (known: hang, power, leak)", text));
}

emulator::Tick duration_of(std::string_view spec, std::string_view text) {
  for (const auto& [unit, ticks] : kUnits) {
    if (text.size() <= unit.size() || !text.ends_with(unit))
      continue;
    const std::string_view number = text.substr(0, text.size() - unit.size());
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error != std::errc() || end != number.data() + number.size())
      break;
    const double ticks_wanted = value * static_cast<double>(ticks);
    if (!(ticks_wanted >= 0.0) || ticks_wanted > static_cast<double>(kLongestOffset))
      fail(spec, fmt::format("the time '{}' is not between 0 and 3600 s", text));
    return static_cast<emulator::Tick>(std::llround(ticks_wanted));
  }
  fail(spec, fmt::format("'{}' is no time: write a number and s, ms or us (e.g. 1.05s)", text));
}

bool is_name(std::string_view text) {
  if (text.empty())
    return false;
  for (const char c : text)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
      return false;
  return std::isalpha(static_cast<unsigned char>(text.front()));
}

} // namespace

const char* to_string(Fault::Kind kind) {
  switch (kind) {
  case Fault::Kind::hang:
    return "hang";
  case Fault::Kind::power_loss:
    return "power";
  case Fault::Kind::leak:
    return "leak";
  }
  return "?";
}

Fault parse_fault(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::size_t at = spec.find('@');
  if (colon == std::string_view::npos || at == std::string_view::npos || at < colon)
    fail(spec, "write KIND:MODULE@WHEN, e.g. hang:module1@1.05s or power:module0@matching+0.5s");
  Fault fault;
  fault.kind = kind_of(spec, spec.substr(0, colon));
  fault.module = std::string(spec.substr(colon + 1, at - colon - 1));
  if (!is_name(fault.module))
    fail(spec, fmt::format("'{}' is no module name", fault.module));
  const std::string_view when = spec.substr(at + 1);
  if (when.empty())
    fail(spec, "nothing after '@': give a time (1.05s) or a stage (matching+0.5s)");
  if (when.front() == '-')
    fail(spec, "times count from the cycle's start and cannot be negative");
  if (std::isdigit(static_cast<unsigned char>(when.front())) || when.front() == '.') {
    fault.offset = duration_of(spec, when);
    return fault;
  }
  const std::size_t plus = when.find('+');
  fault.stage = std::string(when.substr(0, plus));
  if (!is_name(fault.stage))
    fail(spec, fmt::format("'{}' is no stage name", fault.stage));
  if (plus != std::string_view::npos)
    fault.offset = duration_of(spec, when.substr(plus + 1));
  return fault;
}

std::string describe(const Fault& fault) {
  const std::string when = fmt::format("{}s", emulator::to_seconds(fault.offset));
  if (fault.stage.empty())
    return fmt::format("{}:{}@{}", to_string(fault.kind), fault.module, when);
  return fmt::format("{}:{}@{}+{}", to_string(fault.kind), fault.module, fault.stage, when);
}

} // namespace marsokhod::overswitch
