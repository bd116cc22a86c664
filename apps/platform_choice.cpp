// Shipped platforms by name, other platforms by file.

#include "platform_choice.hpp"

#include "command.hpp"

#include <fmt/format.h>

#include <filesystem>

namespace marsokhod::apps {

emulator::PlatformSpec platform_for(const std::string& name) {
  if (std::filesystem::exists(name) || name.find('/') != std::string::npos)
    return emulator::load_platform(name);
  return emulator::load_platform(
      emulator::find_platform_file(name.ends_with(".toml") ? name : name + ".toml"));
}

void require_overswitch(const emulator::PlatformSpec& platform, const std::string& named_in) {
  if (platform.overswitch)
    return;
  throw CommandError(fmt::format("{}: platform {} has no [overswitch] table, so no module can fail "
                                 "over (the onboard platform has one)",
                                 named_in, platform.name));
}

} // namespace marsokhod::apps
