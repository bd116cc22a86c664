// Typed, checked reads of one TOML table, failing with the file kind's own error.
#include "marsokhod/io/formats/toml_table.hpp"

#include "marsokhod/io/formats/toml_file.hpp"

#include <fmt/format.h>

#include <cmath>

namespace marsokhod::io {

TomlTable::TomlTable(const toml::table& table, std::string file, std::string where,
                     KeyedErrorThrower thrower, std::string prefix)
    : table_(table), file_(std::move(file)), where_(std::move(where)), thrower_(thrower),
      prefix_(std::move(prefix)) {}

const toml::node* TomlTable::find(std::string_view key) {
  read_.emplace(key);
  return table_.get(key);
}

const toml::node& TomlTable::require(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr)
    raise(line(), key, where_.empty() ? "missing" : fmt::format("missing in {}", where_));
  return *node;
}

bool TomlTable::absent(std::string_view key) {
  return find(key) == nullptr;
}

std::int64_t TomlTable::integer_of(std::string_view key, const toml::node& node) const {
  // toml++ stores every TOML integer as an int64 and refuses a literal beyond it at parse time,
  // so nothing can have wrapped before this point.
  const auto value = node.value_exact<std::int64_t>();
  if (!value)
    fail(key, fmt::format("must be an integer, not {}", toml_type_name(node.type())));
  return *value;
}

std::optional<std::int64_t> TomlTable::optional_integer(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr)
    return std::nullopt;
  return integer_of(key, *node);
}

void TomlTable::fail_range(std::string_view key, std::int64_t value, const std::string& low,
                           const std::string& high, std::string_view why) const {
  fail(key, fmt::format("{} is out of range: it must be between {} and {}{}{}", value, low, high,
                        why.empty() ? "" : " ", why));
}

std::optional<double> TomlTable::optional_number(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr)
    return std::nullopt;
  // An integer is taken as the nearest double (toml++'s value<double>() refuses one that does
  // not convert exactly, which would call 2^63 - 1 "not a number").
  if (node->is_integer())
    return static_cast<double>(integer_of(key, *node));
  const auto value = node->value_exact<double>();
  if (!value)
    fail(key, fmt::format("must be a finite number, not {}", toml_type_name(node->type())));
  if (!std::isfinite(*value))
    fail(key, fmt::format("must be a finite number, not {}", *value));
  return value;
}

double TomlTable::number_in(std::string_view key, double low, double high) {
  require(key);
  const double value = *optional_number(key);
  if (!(value >= low && value <= high))
    fail(key, fmt::format("{} is out of range: it must be {}", value, range_text(low, high)));
  return value;
}

std::string TomlTable::string(std::string_view key) {
  require(key);
  return *optional_string(key);
}

std::optional<std::string> TomlTable::optional_string(std::string_view key) {
  const toml::node* node = find(key);
  if (node == nullptr)
    return std::nullopt;
  auto value = node->value_exact<std::string>();
  if (!value)
    fail(key, fmt::format("must be a string, not {}", toml_type_name(node->type())));
  return value;
}

bool TomlTable::boolean(std::string_view key, bool fallback) {
  const toml::node* node = find(key);
  if (node == nullptr)
    return fallback;
  const auto value = node->value_exact<bool>();
  if (!value)
    fail(key, fmt::format("must be true or false, not {}", toml_type_name(node->type())));
  return *value;
}

const toml::table* TomlTable::optional_table(std::string_view key) {
  const toml::node* node = find(key);
  if (node != nullptr && !node->is_table())
    fail(key, fmt::format("must be a table, not {}", toml_type_name(node->type())));
  return node == nullptr ? nullptr : node->as_table();
}

const toml::array* TomlTable::optional_array(std::string_view key) {
  const toml::node* node = find(key);
  if (node != nullptr && !node->is_array())
    fail(key, fmt::format("must be an array, not {}", toml_type_name(node->type())));
  return node == nullptr ? nullptr : node->as_array();
}

void TomlTable::expect_keys(std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys)
    read_.emplace(key);
}

void TomlTable::reject_unknown_keys() const {
  reject_unknown_keys(where_.empty() ? "unknown key" : fmt::format("unknown key in {}", where_));
}

void TomlTable::reject_unknown_keys(std::string_view problem) const {
  for (const auto& [key, node] : table_)
    if (!read_.contains(key.str()))
      raise(static_cast<int>(key.source().begin.line), key.str(), std::string(problem));
}

void TomlTable::fail(std::string_view key, const std::string& problem) const {
  raise(line_of(key), key, with_where(problem));
}

int TomlTable::line_of(std::string_view key) const {
  const toml::node* node = table_.get(key);
  if (node == nullptr)
    return line();
  return static_cast<int>(node->source().begin.line);
}

int TomlTable::line() const {
  return static_cast<int>(table_.source().begin.line);
}

std::string TomlTable::key_name(std::string_view key) const {
  if (prefix_.empty())
    return std::string(key);
  return fmt::format("{}.{}", prefix_, key);
}

std::string TomlTable::with_where(const std::string& problem) const {
  if (where_.empty())
    return problem;
  return fmt::format("{} ({})", problem, where_);
}

void TomlTable::raise(int line, std::string_view key, const std::string& problem) const {
  if (thrower_ != nullptr)
    thrower_(file_, line, key_name(key), problem);
  // Also when a thrower returned: the read must not go on.
  throw KeyedFileError(file_, line, key_name(key), problem);
}

} // namespace marsokhod::io
