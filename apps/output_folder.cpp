// Creating a command's output folder, with a message naming it when that fails.

#include "command.hpp"

#include <fmt/format.h>

#include <system_error>

namespace marsokhod::apps {

void prepare_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw CommandError(fmt::format("{}: cannot create the output folder{}", folder.string(),
                                   error ? ": " + error.message() : std::string()));
}

} // namespace marsokhod::apps
