// Joining a name taken from an input (a pair name, a process name) to an output folder safely.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace marsokhod::io {

/// Why `name` cannot name a file or folder inside an output folder, or nothing when it can:
/// it must be non-empty, relative, without "." or ".." parts, NUL or control characters.
std::optional<std::string> contained_name_problem(std::string_view name);

/// folder / name, for a name that passed contained_name_problem; otherwise an InputError
/// "<what> '<name>' <problem>".
std::filesystem::path path_inside(const std::filesystem::path& folder, std::string_view name,
                                  std::string_view what);

} // namespace marsokhod::io
