// One table of a TOML input file, read with typed getters that fail naming file, line and key.
#pragma once

#include "marsokhod/io/formats/keyed_file_error.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <toml++/toml.h>

#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace marsokhod::io {

/// One table of a TOML file: typed getters that fail with the file, the line and the key, and a
/// final check that no key was left unread (an unknown key is an error, not a comment: a misspelt
/// optional key would otherwise be silently ignored).
///
/// Errors are thrown through the thrower given, so that each file kind throws its own type
/// (io::throw_keyed<PlatformError>); without one they are KeyedFileErrors.
/// `where` names the table ("[platform]", "a [[node]]") and ends every problem as " (WHERE)"
/// (a missing or unknown key is "missing in WHERE", "unknown key in WHERE"); a file whose keys
/// say where they are leaves it empty and gives a `prefix` instead, which errors put before each
/// key ("process[2]" names 'process[2].node').
///
/// Integers are read as the file's int64, and a range is checked on that before the value is
/// narrowed to the field's type, so 2^32 + 3 is out of range, never 3.
class TomlTable {
public:
  TomlTable(const toml::table& table, std::string file, std::string where,
            KeyedErrorThrower thrower = nullptr, std::string prefix = {});

  /// An integer in [low, high] as an Int. `why` (optional) continues the message with the unit
  /// and where the range comes from: "V is out of range: it must be between L and H why".
  template <std::integral Int>
  Int integer_in(std::string_view key, Int low, Int high, std::string_view why = {}) {
    return in_range(key, integer_of(key, require(key)), low, high, why);
  }
  /// integer_in, or `fallback` when the key is absent.
  template <std::integral Int>
  Int optional_integer_in(std::string_view key, Int low, Int high, Int fallback,
                          std::string_view why = {}) {
    if (absent(key))
      return fallback;
    return integer_in(key, low, high, why);
  }
  /// An array of integers, each in [low, high]; empty when the key is absent.
  template <std::integral Int>
  std::vector<Int> integers_in(std::string_view key, Int low, Int high, std::string_view why = {}) {
    std::vector<Int> values;
    if (const toml::array* array = optional_array(key))
      for (const toml::node& element : *array)
        values.push_back(in_range(key, integer_of(key, element), low, high, why));
    return values;
  }
  /// Any integer, as the file's int64, or nullopt when the key is absent.
  std::optional<std::int64_t> optional_integer(std::string_view key);

  /// A finite number in [low, high]; a TOML integer is taken as its value.
  double number_in(std::string_view key, double low, double high);
  /// Any finite number, or nullopt when the key is absent.
  std::optional<double> optional_number(std::string_view key);

  std::string string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  /// true or false, or `fallback` when the key is absent.
  bool boolean(std::string_view key, bool fallback);
  const toml::table* optional_table(std::string_view key);
  const toml::array* optional_array(std::string_view key);

  /// Counts `keys` as read, so that reject_unknown_keys() can run before the getters do.
  void expect_keys(std::initializer_list<std::string_view> keys);
  /// Fails on the first key no getter asked for: "unknown key in WHERE".
  void reject_unknown_keys() const;
  /// The same, saying `problem` instead.
  void reject_unknown_keys(std::string_view problem) const;

  /// Fails at the key's line (the table's when the key is absent).
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  /// The line of the key's value, or of the table when it lacks the key.
  int line_of(std::string_view key) const;
  /// The line of the table itself (0 for a whole file).
  int line() const;
  /// The key as errors name it: "process[2].node" under a prefix.
  std::string key_name(std::string_view key) const;
  const std::string& file() const { return file_; }
  const toml::table& table() const { return table_; }

private:
  const toml::node* find(std::string_view key);
  const toml::node& require(std::string_view key);
  /// Marks the key read and tells whether the table lacks it.
  bool absent(std::string_view key);
  std::int64_t integer_of(std::string_view key, const toml::node& node) const;
  std::string with_where(const std::string& problem) const;
  [[noreturn]] void raise(int line, std::string_view key, const std::string& problem) const;
  [[noreturn]] void fail_range(std::string_view key, std::int64_t value, const std::string& low,
                               const std::string& high, std::string_view why) const;

  template <std::integral Int>
  Int in_range(std::string_view key, std::int64_t value, Int low, Int high,
               std::string_view why) const {
    if (std::cmp_less(value, low) || std::cmp_greater(value, high))
      fail_range(key, value, std::to_string(low), std::to_string(high), why);
    return *narrow<Int>(value); // [low, high] lies inside Int
  }

  const toml::table& table_;
  std::string file_;
  std::string where_;
  KeyedErrorThrower thrower_;
  std::string prefix_;
  std::set<std::string, std::less<>> read_;
};

} // namespace marsokhod::io
