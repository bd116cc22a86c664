// The lighting presets (high sun, overexposed, dark and wet, low sun) and their names.

#include "marsokhod/world/lighting/lighting.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace marsokhod::world {
namespace {

struct NamedPreset {
  LightPreset preset;
  std::string_view name;
};

constexpr std::array<NamedPreset, 4> kPresets{{{LightPreset::high_sun, "high-sun"},
                                               {LightPreset::overexposed, "overexposed"},
                                               {LightPreset::dark_wet, "dark-wet"},
                                               {LightPreset::low_sun, "low-sun"}}};

Lighting high_sun() {
  Lighting light;
  light.name = "high-sun";
  light.sun_elevation_deg = 60.0;
  light.sun_azimuth_deg = 135.0;
  light.sun = 1.0;
  light.ambient = 0.25;
  light.exposure = 180.0; // mean regolith at about grey 110, rocks and shadows well inside 0..255
  light.sky_grey = 200.0;
  return light;
}

/// The Mojave pair (paper, fig. 7): high sun, exposure so long that bright sand saturates.
Lighting overexposed() {
  Lighting light = high_sun();
  light.name = "overexposed";
  light.exposure = 380.0; // flat regolith brighter than albedo 0.6 clips at 255
  light.sky_grey = 255.0;
  return light;
}

/// The Kamchatka pair (paper, fig. 6): overcast, wet dark volcanic dust, little contrast.
Lighting dark_wet() {
  Lighting light;
  light.name = "dark-wet";
  light.sun_elevation_deg = 45.0;
  light.sun_azimuth_deg = 135.0;
  light.sun = 0.25; // the sun behind clouds: weak direct light, soft shadows mostly lost
  light.ambient = 0.75;
  light.albedo_scale = 0.35;
  light.albedo_contrast = 0.6;
  light.exposure = 220.0;
  light.sky_grey = 150.0;
  return light;
}

/// Sun 12 degrees above the horizon: long cast shadows, little sky light.
Lighting low_sun() {
  Lighting light;
  light.name = "low-sun";
  light.sun_elevation_deg = 12.0;
  light.sun_azimuth_deg = 135.0;
  light.sun = 1.0;
  light.ambient = 0.08;
  light.exposure = 500.0; // flat regolith at about grey 80; sun-facing slopes brighter
  light.sky_grey = 230.0;
  return light;
}

} // namespace

Lighting lighting_preset(LightPreset preset) {
  switch (preset) {
  case LightPreset::high_sun:
    return high_sun();
  case LightPreset::overexposed:
    return overexposed();
  case LightPreset::dark_wet:
    return dark_wet();
  case LightPreset::low_sun:
    return low_sun();
  }
  throw std::invalid_argument("lighting_preset: unknown preset");
}

LightPreset parse_light_preset(std::string_view name) {
  for (const NamedPreset& entry : kPresets)
    if (entry.name == name)
      return entry.preset;
  std::string valid;
  for (const NamedPreset& entry : kPresets)
    valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
  throw std::invalid_argument("unknown lighting preset '" + std::string(name) +
                              "' (valid: " + valid + ")");
}

std::string_view to_string(LightPreset preset) {
  for (const NamedPreset& entry : kPresets)
    if (entry.preset == preset)
      return entry.name;
  throw std::invalid_argument("to_string: unknown lighting preset");
}

} // namespace marsokhod::world
