// Creating the folders evaluations write their pictures and disparities into.
#pragma once

#include <filesystem>

namespace marsokhod::eval {

/// Creates `folder` and its parents when missing; throws EvaluationError naming the folder when
/// it cannot be created or is not a directory.
void prepare_output_folder(const std::filesystem::path& folder);

} // namespace marsokhod::eval
