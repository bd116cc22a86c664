// Creating the folders evaluations write into, with errors naming the folder.
#include "common/output_folder.hpp"

#include "marsokhod/eval/common/errors.hpp"

#include <fmt/format.h>

#include <string>
#include <system_error>

namespace marsokhod::eval {

void prepare_output_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw EvaluationError(fmt::format("{}: cannot create the output folder{}", folder.string(),
                                      error ? ": " + error.message() : std::string()));
}

} // namespace marsokhod::eval
