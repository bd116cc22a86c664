// A project TOML file (rig, calibration) being read, with errors naming file and line.
#pragma once

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/toml_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <filesystem>
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

  /// The whole file, parsed (read through the bounded reader: regular files only, size limit).
  toml::table parse() const {
    try {
      return io::parse_toml_file(path_, kind_ + " file");
    } catch (const io::InputError& error) {
      throw Error(error.what());
    }
  }

  [[noreturn]] void fail(const toml::source_region& where, const std::string& problem) const {
    throw Error(fmt::format("{}: {}", io::toml_place(path_, where), problem));
  }
  /// A problem of the whole file (a missing table or key has no place of its own).
  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(fmt::format("{}: {}", path_.string(), problem));
  }

private:
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
