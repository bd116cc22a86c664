// The platform a campaign file names.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

namespace marsokhod::eval {

/// The campaign's platform: a shipped platform's name, or a file relative to the campaign
/// file's folder. emulator::PlatformError when it cannot be read, overswitch::NoOverswitchError
/// (naming the campaign file) when it has no [overswitch] table.
emulator::PlatformSpec campaign_platform(const overswitch::CampaignSpec& spec);

} // namespace marsokhod::eval
