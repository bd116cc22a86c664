// Typed, checked reads of one TOML table of a platform or processor file.

#include "platform/platform_table_reader.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/toml_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace marsokhod::emulator::detail {

TableReader::TableReader(const toml::table& table, std::string file, std::string where)
    : table_(table), file_(std::move(file)), where_(std::move(where)) {}

const toml::node* TableReader::find(std::string_view key) {
  read_.emplace(key);
  return table_.get(key);
}

const toml::node& TableReader::require(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr)
    throw PlatformError(file_, static_cast<int>(table_.source().begin.line), std::string(key),
                        fmt::format("missing in {}", where_));
  return *node;
}

bool TableReader::absent(std::string_view key) {
  read_.emplace(key);
  return table_.get(key) == nullptr;
}

std::int64_t TableReader::integer_of(std::string_view key, const toml::node& node) const {
  // toml++ stores every TOML integer as an int64 and refuses a literal beyond it at parse time,
  // so nothing can have wrapped before this point.
  const auto value = node.value_exact<std::int64_t>();
  if (!value)
    fail(key, "must be an integer");
  return *value;
}

std::int64_t TableReader::raw_integer(std::string_view key) {
  return integer_of(key, require(key));
}

void TableReader::fail_range(std::string_view key, std::int64_t value, const std::string& low,
                             const std::string& high, std::string_view why) const {
  fail(key, fmt::format("{} is out of range: it must be between {} and {}{}{}", value, low, high,
                        why.empty() ? "" : " ", why));
}

double TableReader::number_in(std::string_view key, double low, double high) {
  const toml::node& node = require(key);
  // An integer is taken as the nearest double (toml++'s value<double>() refuses one that does
  // not convert exactly, which would call 2^63 - 1 "not a number").
  const auto value = node.is_integer()
                         ? std::optional<double>(static_cast<double>(integer_of(key, node)))
                         : node.value_exact<double>();
  if (!value || !std::isfinite(*value))
    fail(key, "must be a finite number");
  if (!(*value >= low && *value <= high))
    fail(key, fmt::format("{} is out of range: it must be {}", *value, io::range_text(low, high)));
  return *value;
}

std::string TableReader::string(std::string_view key) {
  const auto value = require(key).value_exact<std::string>();
  if (!value)
    fail(key, "must be a string");
  return *value;
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  if (absent(key))
    return std::nullopt;
  return string(key);
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* node = find(key);
  if (node == nullptr)
    return fallback;
  const auto value = node->value_exact<bool>();
  if (!value)
    fail(key, "must be true or false");
  return *value;
}

const toml::table* TableReader::optional_table(std::string_view key) {
  const toml::node* node = find(key);
  if (node != nullptr && !node->is_table())
    fail(key, "must be a table");
  return node == nullptr ? nullptr : node->as_table();
}

const toml::array* TableReader::optional_array(std::string_view key) {
  const toml::node* node = find(key);
  if (node != nullptr && !node->is_array())
    fail(key, "must be an array");
  return node == nullptr ? nullptr : node->as_array();
}

void TableReader::reject_unknown_keys() const {
  for (const auto& [key, node] : table_)
    if (!read_.contains(key.str()))
      throw PlatformError(file_, static_cast<int>(key.source().begin.line), std::string(key.str()),
                          fmt::format("unknown key in {}", where_));
}

void TableReader::fail(std::string_view key, const std::string& problem) const {
  throw PlatformError(file_, line_of(key), std::string(key),
                      fmt::format("{} ({})", problem, where_));
}

int TableReader::line_of(std::string_view key) const {
  const toml::node* node = table_.get(key);
  const auto& region = node != nullptr ? node->source() : table_.source();
  return static_cast<int>(region.begin.line);
}

toml::table parse_toml_file(const std::string& file, std::string_view kind) {
  try {
    return io::parse_toml_file(file, kind);
  } catch (const io::InputError& error) {
    // A syntax error has a line; a file that could not be read has none.
    if (error.line() > 0)
      throw PlatformError(file, error.line(), "", error.problem());
    throw UnreadableFileError(file, 0, "", error.problem());
  }
}

} // namespace marsokhod::emulator::detail
