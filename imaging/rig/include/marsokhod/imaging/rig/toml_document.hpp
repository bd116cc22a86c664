// A project TOML file (rig, calibration) being read, with errors naming file and line.
#pragma once

#include <fmt/format.h>
#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace marsokhod::imaging::detail {

/// A project TOML file (rig, calibration) being read: every problem becomes an Error whose
/// message names the file and, where the problem has one, the line and column.
template <class Error>
class TomlDocument {
public:
  /// kind: what the file is, for "cannot open rig file".
  TomlDocument(std::filesystem::path path, std::string_view kind)
      : path_(std::move(path)), kind_(kind) {}

  const std::filesystem::path& path() const { return path_; }

  /// The whole file, parsed.
  toml::table parse() const {
    const std::string text = read_text();
    try {
      return toml::parse(text, path_.string());
    } catch (const toml::parse_error& error) {
      fail(error.source(), fmt::format("TOML syntax error: {} in \"{}\"", error.description(),
                                       line_of(text, error.source().begin.line)));
    }
  }

  [[noreturn]] void fail(const toml::source_region& where, const std::string& problem) const {
    throw Error(
        fmt::format("{}:{}:{}: {}", path_.string(), where.begin.line, where.begin.column, problem));
  }
  /// A problem of the whole file (a missing table or key has no place of its own).
  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(fmt::format("{}: {}", path_.string(), problem));
  }

private:
  std::string read_text() const {
    std::ifstream in(path_, std::ios::binary);
    if (!in || std::filesystem::is_directory(path_))
      fail(fmt::format("cannot open {} file", kind_));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // The offending line, so a syntax error also shows the key it is about.
  static std::string line_of(const std::string& text, toml::source_index line) {
    std::istringstream lines(text);
    std::string current;
    for (toml::source_index n = 1; std::getline(lines, current); ++n)
      if (n == line)
        return current;
    return {};
  }

  std::filesystem::path path_;
  std::string kind_;
};

/// Shortest text that reads back to the same double, always a TOML float.
inline std::string toml_float(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eE") == std::string::npos)
    text += ".0";
  return text;
}

} // namespace marsokhod::imaging::detail
