// A platform named on the command line: a file, or a shipped platform's name.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"

#include <string>

namespace marsokhod::apps {

/// Loads `name` as a file when one exists there or it has a '/', else the shipped platform of
/// that name ("onboard", "pc-card.toml"); emulator::PlatformError when it cannot be read.
emulator::PlatformSpec platform_for(const std::string& name);

} // namespace marsokhod::apps
