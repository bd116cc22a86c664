// A platform named on the command line: a file, or a shipped platform's name; what a command
// needs of it.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"

#include <string>

namespace marsokhod::apps {

/// Loads `name` as a file when one exists there or it has a '/', else the shipped platform of
/// that name ("onboard", "pc-card.toml"); emulator::PlatformError when it cannot be read.
emulator::PlatformSpec platform_for(const std::string& name);

/// Refuses, with a CommandError naming `named_in` (the file that chose the platform), a platform
/// without an [overswitch] table: the fault and campaign commands need one to fail a module over.
void require_overswitch(const emulator::PlatformSpec& platform, const std::string& named_in);

} // namespace marsokhod::apps
