// Typed, checked reads of one TOML table of a platform file.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace marsokhod::emulator::detail {

/// Reads one TOML table of a platform file: typed getters that fail with file, line and key,
/// and a final check that no key was left unread (an unknown key is an error, not a comment).
class TableReader {
public:
  TableReader(const toml::table& table, std::string file, std::string where);

  std::int64_t integer(std::string_view key);
  std::optional<std::int64_t> optional_integer(std::string_view key);
  /// An integer that must be at least `minimum`.
  std::int64_t integer_at_least(std::string_view key, std::int64_t minimum);
  double number(std::string_view key);
  std::optional<double> optional_number(std::string_view key);
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

  const toml::table& table_;
  std::string file_;
  std::string where_;
  std::set<std::string, std::less<>> read_;
};

/// Parses a TOML file, turning syntax errors and unreadable files into PlatformError.
toml::table parse_toml_file(const std::string& file);

} // namespace marsokhod::emulator::detail
