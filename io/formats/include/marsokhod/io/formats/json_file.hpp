// Parsing a JSON input file through the bounded text reader.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string_view>

namespace marsokhod::io {

/// `path` parsed as JSON. kind names the file ("scene file"). An unreadable file and a syntax
/// error are InputErrors naming the file (and the byte where parsing stopped). Nesting deeper
/// than kMaxJsonDepth is refused, so that no file can exhaust the stack.
nlohmann::json parse_json_file(const std::filesystem::path& path, std::string_view kind);

/// Deepest nesting of arrays and objects a JSON input may have.
inline constexpr int kMaxJsonDepth = 64;

} // namespace marsokhod::io
