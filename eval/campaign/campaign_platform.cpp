// A campaign's platform, by name or by a path beside the campaign file.

#include "marsokhod/eval/campaign/campaign_platform.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"
#include "marsokhod/overswitch/supervision/overswitch.hpp"

#include <fmt/format.h>

#include <filesystem>

namespace marsokhod::eval {

emulator::PlatformSpec campaign_platform(const overswitch::CampaignSpec& spec) {
  const bool is_path =
      spec.platform.find('/') != std::string::npos || spec.platform.ends_with(".toml");
  const std::string name =
      is_path ? (std::filesystem::path(spec.source).parent_path() / spec.platform).string()
              : spec.platform;
  emulator::PlatformSpec platform;
  try {
    platform = emulator::load_named_platform(name);
  } catch (const emulator::PlatformError& error) {
    // A platform file with an error names itself; a platform found nowhere is the campaign
    // file's error, and the campaign file is what the message must name.
    if (std::filesystem::exists(error.file()))
      throw;
    throw overswitch::CampaignError(spec.source, 0, "platform",
                                    fmt::format("'{}': {}", spec.platform, error.problem()));
  }
  overswitch::require_overswitch(platform, spec.source);
  return platform;
}

} // namespace marsokhod::eval
