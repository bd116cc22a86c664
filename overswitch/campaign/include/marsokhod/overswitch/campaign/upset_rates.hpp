// Upset rates of radiation environments, per bit of memory and day, with their sources.
#pragma once

#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace marsokhod::overswitch {

/// A preset environment by name (cruise, mars-surface, leo); nothing for an unknown name.
std::optional<UpsetRate> upset_preset(std::string_view name);

/// The presets' names, comma-separated, for messages.
std::string upset_preset_names();

} // namespace marsokhod::overswitch
