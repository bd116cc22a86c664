// The options a single traverse and a sweep of them share: the course and where it runs.
#pragma once

#include "marsokhod/eval/traverse/traverse.hpp"

#include <CLI/CLI.hpp>

namespace marsokhod::apps {

/// The image size the onboard computer's two 256 KB modules hold (docs/emulated-navigation.md).
inline constexpr int kOnboardImagePx = 128;

/// --slope, --light, --platform, --drive-m, --hazard-memory, --slip, --faults and --goal-m,
/// read into `course`.
void add_course_options(CLI::App* app, eval::TraverseSettings& course);

/// Before any course runs: --faults needs an emulated --platform, the same the campaign file
/// names (UsageError), and a campaign file that reads (its own error, naming file, line, key).
void check_course_faults(const eval::TraverseSettings& course);

} // namespace marsokhod::apps
