// Parsing a TOML input file through the bounded text reader, errors naming file, line and text.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace marsokhod::io {

/// `path` parsed as TOML. kind names the file ("rig file"). An unreadable file and a syntax
/// error are InputErrors: "FILE:LINE: TOML syntax error at column C: ... in \"the line\"".
toml::table parse_toml_file(const std::filesystem::path& path, std::string_view kind);

/// "FILE:LINE:COLUMN: problem" for a place in a TOML file (or "FILE: problem" without one).
std::string toml_place(const std::filesystem::path& path, const toml::source_region& where);

/// "a table", "an integer": a TOML node type as messages name it.
std::string_view toml_type_name(toml::node_type type);

} // namespace marsokhod::io
