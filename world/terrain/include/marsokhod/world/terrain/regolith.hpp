// The bare regolith: undulation, regional slope, roughness and albedo of the site.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/world/terrain/height_field.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <cstdint>

namespace marsokhod::world {

/// Mean albedo of the regolith before variation; rocks are darker or lighter.
inline constexpr double kRegolithAlbedo = 0.55;

/// Adds the bare regolith to the heights: gentle undulation (fractal value noise with
/// wavelengths 24 m down to 0.75 m whose amplitudes sum to undulation_m), the regional slope
/// (regional_slope_deg downhill towards a random azimuth, zero at the origin) and mm-cm
/// roughness (wavelengths 32 cm down to 4 cm plus per-node jitter).
void shape_regolith(const TerrainSettings& settings, HeightField& height);

/// Regolith albedo at every node of the height field: kRegolithAlbedo with low-frequency
/// variation (6 m, 2 m, 0.6 m) and fine speckle (15 cm, 5 cm, per node).
imaging::Image<float> regolith_albedo(const HeightField& height, std::uint64_t seed);

} // namespace marsokhod::world
