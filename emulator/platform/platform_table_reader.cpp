// Typed, checked reads of one TOML table of a platform file.

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

std::int64_t TableReader::integer(std::string_view key) {
  const auto value = require(key).value_exact<std::int64_t>();
  if (!value)
    fail(key, "must be an integer");
  return *value;
}

std::optional<std::int64_t> TableReader::optional_integer(std::string_view key) {
  if (table_.get(key) == nullptr) {
    read_.emplace(key);
    return std::nullopt;
  }
  return integer(key);
}

std::int64_t TableReader::integer_at_least(std::string_view key, std::int64_t minimum) {
  const std::int64_t value = integer(key);
  if (value < minimum)
    fail(key, fmt::format("{} is impossible, it must be at least {}", value, minimum));
  return value;
}

double TableReader::number(std::string_view key) {
  const toml::node& node = require(key);
  const auto value = node.is_integer() ? node.value<double>() : node.value_exact<double>();
  if (!value || !std::isfinite(*value))
    fail(key, "must be a number");
  return *value;
}

std::optional<double> TableReader::optional_number(std::string_view key) {
  if (table_.get(key) == nullptr) {
    read_.emplace(key);
    return std::nullopt;
  }
  return number(key);
}

std::string TableReader::string(std::string_view key) {
  const auto value = require(key).value_exact<std::string>();
  if (!value)
    fail(key, "must be a string");
  return *value;
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  if (table_.get(key) == nullptr) {
    read_.emplace(key);
    return std::nullopt;
  }
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

toml::table parse_toml_file(const std::string& file) {
  try {
    return io::parse_toml_file(file, "platform file");
  } catch (const io::InputError& error) {
    throw PlatformError(file, error.line(), "", error.problem());
  }
}

} // namespace marsokhod::emulator::detail
