// Shipped platforms by name, other platforms by file.

#include "platform_choice.hpp"

#include <filesystem>

namespace marsokhod::apps {

emulator::PlatformSpec platform_for(const std::string& name) {
  if (std::filesystem::exists(name) || name.find('/') != std::string::npos)
    return emulator::load_platform(name);
  return emulator::load_platform(
      emulator::find_platform_file(name.ends_with(".toml") ? name : name + ".toml"));
}

} // namespace marsokhod::apps
