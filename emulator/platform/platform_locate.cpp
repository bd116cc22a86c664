// Finding a platform file by name in the folders it may be shipped in, or by its path.

#include "marsokhod/emulator/platform/platform.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <system_error>
#include <vector>

namespace marsokhod::emulator {
namespace {

std::filesystem::path executable_folder() {
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : self.parent_path();
}

std::vector<std::filesystem::path> search_folders() {
  std::vector<std::filesystem::path> folders;
  if (const char* env = std::getenv("MARSOKHOD_PLATFORMS"); env != nullptr && *env != '\0')
    folders.emplace_back(env);
  folders.emplace_back("platforms");
  for (auto folder = executable_folder(); !folder.empty(); folder = folder.parent_path()) {
    folders.push_back(folder / "platforms");
    folders.push_back(folder / "share" / "marsokhod" / "platforms");
    if (folder == folder.parent_path())
      break;
  }
  return folders;
}

} // namespace

std::filesystem::path find_platform_file(const std::string& name) {
  std::vector<std::string> tried;
  for (const auto& folder : search_folders()) {
    const auto candidate = folder / name;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error))
      return candidate;
    tried.push_back(folder.string());
  }
  throw PlatformError(name, 0, "",
                      fmt::format("no such platform file in {} (set MARSOKHOD_PLATFORMS or pass "
                                  "the file's path)",
                                  fmt::join(tried, ", ")));
}

PlatformSpec load_named_platform(const std::string& name) {
  if (std::filesystem::exists(name) || name.find('/') != std::string::npos)
    return load_platform(name);
  return load_platform(find_platform_file(name.ends_with(".toml") ? name : name + ".toml"));
}

} // namespace marsokhod::emulator
