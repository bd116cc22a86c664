// Names from input files become paths only when they cannot leave their output folder.
#include "marsokhod/io/paths/contained_path.hpp"

#include "marsokhod/io/files/input_error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace marsokhod::io {

std::optional<std::string> contained_name_problem(std::string_view name) {
  if (name.empty())
    return "is empty";
  if (std::any_of(name.begin(), name.end(),
                  [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7F; }))
    return "holds a control character";
  if (name.front() == '/')
    return "is an absolute path; it must stay inside the output folder";
  const std::filesystem::path path(name);
  for (const std::filesystem::path& part : path) {
    if (part == "..")
      return "has a '..' part; it must stay inside the output folder";
    if (part == ".")
      return "has a '.' part";
    if (part.empty())
      return "ends with '/'";
  }
  return std::nullopt;
}

std::filesystem::path path_inside(const std::filesystem::path& folder, std::string_view name,
                                  std::string_view what) {
  if (const auto problem = contained_name_problem(name))
    throw InputError(fmt::format("{} '{}' {}", what, name, *problem));
  return folder / std::filesystem::path(name);
}

} // namespace marsokhod::io
