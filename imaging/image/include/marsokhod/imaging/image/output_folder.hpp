// Creating the folder a command or an evaluation writes its images and files into.
#pragma once

#include <filesystem>

namespace marsokhod::imaging {

/// Creates `folder` and its parents when missing; throws std::runtime_error naming the folder
/// when it cannot be created or is not a directory.
void prepare_output_folder(const std::filesystem::path& folder);

} // namespace marsokhod::imaging
