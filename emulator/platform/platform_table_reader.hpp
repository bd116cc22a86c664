// Typed, checked reads of one TOML table of a platform or processor file.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <toml++/toml.h>

#include <concepts>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace marsokhod::emulator::detail {

/// Reads one TOML table of a platform or processor file: typed getters that fail with file,
/// line and key, and a final check that no key was left unread (an unknown key is an error,
/// not a comment).
///
/// Integers are only read with a range: the range is checked on the file's int64 before the
/// value is narrowed to the field's type, so 2^32 + 3 is out of range, never 3.
class TableReader {
public:
  TableReader(const toml::table& table, std::string file, std::string where);

  /// An integer in [low, high] as an Int. `why` (optional) continues the message with the unit
  /// and where the range comes from: "V is out of range: it must be between L and H why".
  template <std::integral Int>
  Int integer_in(std::string_view key, Int low, Int high, std::string_view why = {}) {
    return in_range(key, raw_integer(key), low, high, why);
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
  /// A finite number in [low, high]; a TOML integer is taken as its value.
  double number_in(std::string_view key, double low, double high);
  std::string string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  bool boolean(std::string_view key, bool fallback);
  const toml::table* optional_table(std::string_view key);
  const toml::array* optional_array(std::string_view key);

  /// Fails on the first key no getter asked for.
  void reject_unknown_keys() const;
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  int line_of(std::string_view key) const;
  const std::string& file() const { return file_; }
  const toml::table& table() const { return table_; }

private:
  const toml::node* find(std::string_view key);
  const toml::node& require(std::string_view key);
  /// Marks the key read and tells whether the table lacks it.
  bool absent(std::string_view key);
  std::int64_t raw_integer(std::string_view key);
  std::int64_t integer_of(std::string_view key, const toml::node& node) const;
  [[noreturn]] void fail_range(std::string_view key, std::int64_t value, const std::string& low,
                               const std::string& high, std::string_view why) const;

  template <std::integral Int>
  Int in_range(std::string_view key, std::int64_t value, Int low, Int high,
               std::string_view why) const {
    if (std::cmp_less(value, low) || std::cmp_greater(value, high))
      fail_range(key, value, std::to_string(low), std::to_string(high), why);
    return *io::narrow<Int>(value); // [low, high] lies inside Int
  }

  const toml::table& table_;
  std::string file_;
  std::string where_;
  std::set<std::string, std::less<>> read_;
};

/// A file that could not be read at all (missing, a directory, a FIFO, too large), as opposed
/// to one whose text is wrong; lets a platform say which of its keys named the file.
class UnreadableFileError : public PlatformError {
public:
  using PlatformError::PlatformError;
};

/// Parses a TOML file through the bounded reader (regular files of at most 16 MiB only: a
/// directory, FIFO or device is refused, never read), turning syntax errors and unreadable
/// files into PlatformError. `kind` names the file in messages ("platform file").
toml::table parse_toml_file(const std::string& file, std::string_view kind);

} // namespace marsokhod::emulator::detail
