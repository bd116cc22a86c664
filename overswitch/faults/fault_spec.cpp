// The `--inject` grammar: KIND:MODULE@WHEN[,KEY=VALUE...].

#include "marsokhod/overswitch/faults/fault.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

namespace marsokhod::overswitch {
namespace {

constexpr emulator::Tick kLongestOffset = 3600 * emulator::kSecond;

constexpr std::array<std::pair<std::string_view, emulator::Tick>, 3> kUnits{
    {{"ms", emulator::kMillisecond}, {"us", emulator::kMicrosecond}, {"s", emulator::kSecond}}};

[[noreturn]] void fail(std::string_view spec, const std::string& problem) {
  throw FaultSpecError(fmt::format("--inject '{}': {}", spec, problem));
}

Fault::Kind kind_of(std::string_view spec, std::string_view text) {
  if (const std::optional<Fault::Kind> kind = parse_fault_kind(text))
    return *kind;
  fail(spec, fmt::format("unknown fault kind '{}' (known: {})", text, fault_kind_names()));
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

/// A whole number in [low, high], decimal or hexadecimal (0x... or #...).
std::uint64_t number_of(std::string_view spec, std::string_view key, std::string_view text,
                        std::uint64_t low, std::uint64_t high) {
  int base = 10;
  std::string_view digits = text;
  if (digits.starts_with("0x") || digits.starts_with("0X")) {
    base = 16;
    digits.remove_prefix(2);
  } else if (digits.starts_with('#')) {
    base = 16;
    digits.remove_prefix(1);
  }
  std::uint64_t value = 0;
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
    fail(spec, fmt::format("{}='{}' is no whole number", key, text));
  if (value < low || value > high)
    fail(spec, fmt::format("{}={} is not between {} and {}", key, text, low, high));
  return value;
}

bool is_name(std::string_view text) {
  if (text.empty())
    return false;
  for (const char c : text)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
      return false;
  return std::isalpha(static_cast<unsigned char>(text.front()));
}

/// The keys each kind takes after its time.
std::vector<std::string_view> keys_of(Fault::Kind kind) {
  switch (kind) {
  case Fault::Kind::hang:
  case Fault::Kind::power_loss:
    return {};
  case Fault::Kind::leak:
    return {"bytes"};
  case Fault::Kind::upset:
    return {"addr", "bit", "buffer", "over"};
  case Fault::Kind::stuck:
    return {"addr", "bit", "buffer", "over", "value"};
  case Fault::Kind::link_down:
    return {"dir", "for"};
  case Fault::Kind::link_bit:
    return {"dir", "byte", "bit"};
  case Fault::Kind::ack_lost:
    return {"dir"};
  }
  return {};
}

LinkDirection direction_of(std::string_view spec, std::string_view text) {
  if (text == "out")
    return LinkDirection::out;
  if (text == "in")
    return LinkDirection::in;
  if (text == "both")
    return LinkDirection::both;
  fail(spec, fmt::format("dir='{}': write out, in or both", text));
}

const char* to_string(LinkDirection direction) {
  switch (direction) {
  case LinkDirection::out:
    return "out";
  case LinkDirection::in:
    return "in";
  case LinkDirection::both:
    return "both";
  }
  return "?";
}

void apply_option(Fault& fault, std::string_view spec, std::string_view key,
                  std::string_view value) {
  const std::vector<std::string_view> keys = keys_of(fault.kind);
  if (std::find(keys.begin(), keys.end(), key) == keys.end())
    fail(spec, keys.empty() ? fmt::format("a {} fault takes no '{}'", to_string(fault.kind), key)
                            : fmt::format("a {} fault takes no '{}' (it takes: {})",
                                          to_string(fault.kind), key, fmt::join(keys, ", ")));
  // Any word of the 32-bit address space: one outside the module's memory is an error of the
  // run, which knows the memory (docs/faults.md), not of the spec.
  if (key == "addr")
    fault.memory.address =
        static_cast<emulator::Address>(number_of(spec, key, value, 0, 0xFFFFFFFFULL));
  else if (key == "bit" && fault.kind == Fault::Kind::link_bit)
    fault.data_bit = static_cast<unsigned>(number_of(spec, key, value, 0, 7));
  else if (key == "bit")
    fault.memory.bit = static_cast<unsigned>(number_of(spec, key, value, 0, 7));
  else if (key == "buffer" && value.empty())
    fail(spec, "buffer= names no buffer");
  else if (key == "buffer")
    fault.memory.buffer = std::string(value);
  else if (key == "over" && value == "allocated")
    fault.memory.over = MemoryTarget::Over::allocated;
  else if (key == "over" && value == "memory")
    fault.memory.over = MemoryTarget::Over::memory;
  else if (key == "over")
    fail(spec, fmt::format("over='{}': write allocated or memory", value));
  else if (key == "value")
    fault.memory.stuck_value = number_of(spec, key, value, 0, 1) == 1;
  else if (key == "bytes")
    fault.leak_bytes = number_of(spec, key, value, 1, 0xFFFFFFFFULL);
  else if (key == "dir")
    fault.direction = direction_of(spec, value);
  else if (key == "for")
    fault.duration = duration_of(spec, value);
  else if (key == "byte")
    fault.byte = number_of(spec, key, value, 0, 1'000'000'000);
}

void check_options(const Fault& fault, std::string_view spec, bool has_over) {
  if (fault.memory.address && !fault.memory.buffer.empty())
    fail(spec, "give addr= or buffer=, not both");
  if (fault.memory.address && has_over)
    fail(spec, "over= draws the address: it goes without addr=");
  if (fault.memory.address && !fault.memory.bit)
    fail(spec, "addr= needs its bit=");
  if (fault.kind == Fault::Kind::link_bit && fault.direction == LinkDirection::both)
    fail(spec, "a bit is flipped on one wire: dir=out or dir=in");
  if (fault.kind == Fault::Kind::ack_lost && fault.direction == LinkDirection::both)
    fail(spec, "an acknowledge is lost on one wire: dir=out or dir=in");
}

/// MODULE, or MODULE.linkN for a fault of a link.
void read_target(Fault& fault, std::string_view spec, std::string_view target) {
  if (!is_link_fault(fault.kind)) {
    if (!is_name(target))
      fail(spec, fmt::format("'{}' is no module name", target));
    fault.module = std::string(target);
    return;
  }
  const std::size_t dot = target.find('.');
  const std::string_view link = dot == std::string_view::npos ? "" : target.substr(dot + 1);
  if (!is_name(target.substr(0, dot)) || link.size() != 5 || !link.starts_with("link") ||
      link[4] < '0' || link[4] > '3')
    fail(spec,
         fmt::format("'{}' is no link: write MODULE.linkN, N from 0 to 3 (module0.link1)", target));
  fault.module = std::string(target.substr(0, dot));
  fault.link = link[4] - '0';
}

void read_when(Fault& fault, std::string_view spec, std::string_view when) {
  if (when.empty())
    fail(spec, "nothing after '@': give a time (1.05s) or a stage (matching+0.5s)");
  if (when.front() == '-')
    fail(spec, "times count from the cycle's start and cannot be negative");
  if (std::isdigit(static_cast<unsigned char>(when.front())) || when.front() == '.') {
    fault.offset = duration_of(spec, when);
    return;
  }
  const std::size_t plus = when.find('+');
  fault.stage = std::string(when.substr(0, plus));
  if (!is_name(fault.stage))
    fail(spec, fmt::format("'{}' is no stage name", fault.stage));
  if (plus != std::string_view::npos)
    fault.offset = duration_of(spec, when.substr(plus + 1));
}

} // namespace

Fault parse_fault(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::size_t at = spec.find('@');
  if (colon == std::string_view::npos || at == std::string_view::npos || at < colon)
    fail(spec, "write KIND:MODULE@WHEN, e.g. hang:module1@1.05s or power:module0@matching+0.5s");
  Fault fault;
  fault.kind = kind_of(spec, spec.substr(0, colon));
  read_target(fault, spec, spec.substr(colon + 1, at - colon - 1));
  if (fault.kind == Fault::Kind::link_bit || fault.kind == Fault::Kind::ack_lost)
    fault.direction = LinkDirection::out; // one wire: by default the one the module drives
  std::string_view rest = spec.substr(at + 1);
  std::size_t comma = rest.find(',');
  read_when(fault, spec, rest.substr(0, comma));
  bool has_over = false;
  std::vector<std::string_view> seen;
  while (comma != std::string_view::npos) {
    rest.remove_prefix(comma + 1);
    comma = rest.find(',');
    const std::string_view option = rest.substr(0, comma);
    const std::size_t equals = option.find('=');
    if (equals == std::string_view::npos)
      fail(spec, fmt::format("'{}' is no KEY=VALUE", option));
    const std::string_view key = option.substr(0, equals);
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      fail(spec, fmt::format("'{}' is given twice", key));
    seen.push_back(key);
    has_over = has_over || key == "over";
    apply_option(fault, spec, key, option.substr(equals + 1));
  }
  check_options(fault, spec, has_over);
  return fault;
}

std::string describe(const Fault& fault) {
  std::string text = fmt::format("{}:{}", to_string(fault.kind), fault.module);
  if (fault.link >= 0)
    text += fmt::format(".link{}", fault.link);
  const std::string when = fmt::format("{}s", emulator::to_seconds(fault.offset));
  text += fault.stage.empty() ? "@" + when : fmt::format("@{}+{}", fault.stage, when);
  const MemoryTarget& m = fault.memory;
  if (is_memory_fault(fault.kind)) {
    if (m.address)
      text += fmt::format(",addr=#{:08X}", *m.address);
    if (m.bit)
      text += fmt::format(",bit={}", *m.bit);
    if (!m.buffer.empty())
      text += ",buffer=" + m.buffer;
    if (!m.address && m.over == MemoryTarget::Over::memory)
      text += ",over=memory";
    if (fault.kind == Fault::Kind::stuck)
      text += fmt::format(",value={}", m.stuck_value ? 1 : 0);
  }
  if (fault.kind == Fault::Kind::leak && fault.leak_bytes)
    text += fmt::format(",bytes={}", *fault.leak_bytes);
  if (is_link_fault(fault.kind) && fault.direction != LinkDirection::both)
    text += fmt::format(",dir={}", to_string(fault.direction));
  if (fault.kind == Fault::Kind::link_down && fault.duration)
    text += fmt::format(",for={}s", emulator::to_seconds(*fault.duration));
  if (fault.kind == Fault::Kind::link_bit) {
    if (fault.byte != 0)
      text += fmt::format(",byte={}", fault.byte);
    if (fault.data_bit)
      text += fmt::format(",bit={}", *fault.data_bit);
  }
  return text;
}

} // namespace marsokhod::overswitch
