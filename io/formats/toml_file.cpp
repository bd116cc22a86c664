// TOML input files: read with the bounded reader, syntax errors shown with their line.
#include "marsokhod/io/formats/toml_file.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/files/text_file.hpp"

#include <fmt/format.h>

#include <sstream>

namespace marsokhod::io {
namespace {

// The offending line, so that a syntax error also shows the key it is about.
std::string line_of(const std::string& text, toml::source_index line) {
  std::istringstream lines(text);
  std::string current;
  for (toml::source_index n = 1; std::getline(lines, current); ++n)
    if (n == line)
      return current;
  return {};
}

} // namespace

std::string toml_place(const std::filesystem::path& path, const toml::source_region& where) {
  if (where.begin.line == 0)
    return path.string();
  return fmt::format("{}:{}:{}", path.string(), where.begin.line, where.begin.column);
}

toml::table parse_toml_file(const std::filesystem::path& path, std::string_view kind) {
  const std::string text = read_text_file(path, kind);
  try {
    return toml::parse(text, path.string());
  } catch (const toml::parse_error& error) {
    const toml::source_position& at = error.source().begin;
    throw InputError(path.string(),
                     fmt::format("TOML syntax error at column {}: {} in \"{}\"", at.column,
                                 error.description(), line_of(text, at.line)),
                     static_cast<int>(at.line));
  }
}

std::string_view toml_type_name(toml::node_type type) {
  switch (type) {
  case toml::node_type::table:
    return "a table";
  case toml::node_type::array:
    return "an array";
  case toml::node_type::string:
    return "a string";
  case toml::node_type::integer:
    return "an integer";
  case toml::node_type::floating_point:
    return "a floating-point number";
  case toml::node_type::boolean:
    return "a boolean";
  case toml::node_type::date:
  case toml::node_type::time:
  case toml::node_type::date_time:
    return "a date or time";
  case toml::node_type::none:
    break;
  }
  return "nothing";
}

} // namespace marsokhod::io
