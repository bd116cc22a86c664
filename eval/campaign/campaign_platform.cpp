// A campaign's platform, by name or by a path beside the campaign file.

#include "marsokhod/eval/campaign/campaign_platform.hpp"

#include "marsokhod/overswitch/supervision/overswitch.hpp"

#include <filesystem>

namespace marsokhod::eval {

emulator::PlatformSpec campaign_platform(const overswitch::CampaignSpec& spec) {
  const bool is_path =
      spec.platform.find('/') != std::string::npos || spec.platform.ends_with(".toml");
  const std::string name =
      is_path ? (std::filesystem::path(spec.source).parent_path() / spec.platform).string()
              : spec.platform;
  emulator::PlatformSpec platform = emulator::load_named_platform(name);
  overswitch::require_overswitch(platform, spec.source);
  return platform;
}

} // namespace marsokhod::eval
