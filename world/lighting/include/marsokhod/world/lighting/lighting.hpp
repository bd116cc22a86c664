// Lighting: sun, sky and exposure, and the named presets of the paper's test sites.
#pragma once

#include <string>
#include <string_view>

namespace marsokhod::world {

/// Named lighting conditions from the paper's test sites plus a low-sun case.
enum class LightPreset { high_sun, overexposed, dark_wet, low_sun };

/// Sun, sky and camera exposure. Shading is Lambertian, so it depends on the terrain and the
/// light only and is computed once per site (LitSurface), not per view.
struct Lighting {
  std::string name;
  double sun_elevation_deg = 60.0;
  double sun_azimuth_deg = 135.0; ///< from east (x) towards north (y)
  double sun = 1.0;               ///< direct irradiance
  double ambient = 0.25;          ///< sky irradiance, unshadowed
  double albedo_scale = 1.0;      ///< darkens the whole site (wet volcanic dust < 1)
  double albedo_contrast = 1.0;   ///< scales albedo variation about its mean
  double exposure = 180.0;        ///< grey level of a unit-radiance surface; > 255 clips
  double sky_grey = 200.0;        ///< grey level where a ray leaves the terrain
  /// Relative amplitude of the procedural texture finer than the terrain grid (0 turns it off);
  /// it is scaled by albedo_contrast like the rest of the albedo variation.
  double fine_texture = 0.06;
};

Lighting lighting_preset(LightPreset preset);
/// "high-sun", "overexposed", "dark-wet", "low-sun"; throws std::invalid_argument otherwise.
LightPreset parse_light_preset(std::string_view name);
std::string_view to_string(LightPreset preset);

} // namespace marsokhod::world
