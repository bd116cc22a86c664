// JSON input files: read with the bounded reader, nesting bounded, errors naming the file.
#include "marsokhod/io/formats/json_file.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/files/text_file.hpp"

#include <fmt/format.h>

#include <string>

namespace marsokhod::io {
namespace {

// nlohmann's parser recurses per level; bound the depth before it runs.
bool nesting_within(const std::string& text, int limit) {
  int depth = 0;
  bool in_string = false;
  bool escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"')
      in_string = true;
    else if (c == '[' || c == '{')
      ++depth;
    else if (c == ']' || c == '}')
      --depth;
    if (depth > limit)
      return false;
  }
  return true;
}

// nlohmann's messages open with "[json.exception.parse_error.101] ", a library detail the user
// has no use for; what follows says where and why.
std::string without_exception_tag(const nlohmann::json::exception& error) {
  const std::string_view message = error.what();
  const std::size_t end = message.find("] ");
  if (message.starts_with("[json.exception.") && end != std::string_view::npos)
    return std::string(message.substr(end + 2));
  return std::string(message);
}

} // namespace

nlohmann::json parse_json_file(const std::filesystem::path& path, std::string_view kind) {
  const std::string text = read_text_file(path, kind);
  if (!nesting_within(text, kMaxJsonDepth))
    throw InputError(path.string(),
                     fmt::format("nests arrays or objects deeper than {} levels; not a {}",
                                 kMaxJsonDepth, kind));
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) { // parse_error, and out_of_range for 1e999
    throw InputError(path.string(),
                     fmt::format("not a {}: {}", kind, without_exception_tag(error)));
  }
}

} // namespace marsokhod::io
