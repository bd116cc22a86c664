// Creating an output folder, with a message naming it when that fails.
#include "marsokhod/imaging/image/output_folder.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <system_error>

namespace marsokhod::imaging {

void prepare_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw std::runtime_error(fmt::format("{}: cannot create the output folder{}", folder.string(),
                                         error ? ": " + error.message() : std::string()));
}

} // namespace marsokhod::imaging
