// The upset-rate presets and where their figures come from.

#include "marsokhod/overswitch/campaign/upset_rates.hpp"

#include <array>

namespace marsokhod::overswitch {
namespace {

const std::array<UpsetRate, 3>& presets() {
  static const std::array<UpsetRate, 3> kPresets{{
      // 71 bit flips a day in the 2.1 Gbit DRAM recorder, from galactic cosmic rays.
      {"cruise", 3.4e-8,
       "Clementine solid-state data recorder, ~71 upsets/day in 2.1 Gbit of DRAM (Garrett et al., "
       "J. Spacecraft and Rockets 32(6), 1995)"},
      // The planet hides half the sky and the atmosphere shields the rest: RAD measured 0.21
      // mGy/day on the surface against 0.48 in cruise, 0.44 of it; the cruise rate times 0.45,
      // the high end of 0.3..0.45.
      {"mars-surface", 1.5e-8,
       "cruise rate x 0.45: MSL RAD absorbed dose 0.21 mGy/day on the surface (Hassler et al., "
       "Science 343, 2014) against 0.48 in cruise (Zeitlin et al., Science 340, 2013)"},
      {"leo", 4.0e-7,
       "Alsat-1 SRAM in low Earth orbit (Bentoutou, IEEE Trans. Aerospace and Electronic Systems "
       "48(1), 2012)"},
  }};
  return kPresets;
}

} // namespace

std::optional<UpsetRate> upset_preset(std::string_view name) {
  for (const UpsetRate& preset : presets())
    if (preset.name == name)
      return preset;
  return std::nullopt;
}

std::string upset_preset_names() {
  std::string names;
  for (const UpsetRate& preset : presets())
    names += (names.empty() ? "" : ", ") + preset.name;
  return names;
}

} // namespace marsokhod::overswitch
