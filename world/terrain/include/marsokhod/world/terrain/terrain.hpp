// The synthetic Mars site: generator settings and the generated terrain.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/lighting/lighting.hpp"
#include "marsokhod/world/lighting/lit_surface.hpp"
#include "marsokhod/world/scene/rover_placement.hpp"
#include "marsokhod/world/terrain/height_field.hpp"
#include "marsokhod/world/terrain/obstacle_map.hpp"

#include <Eigen/Core>

#include <cstdint>

namespace marsokhod::world {

/// What the procedural generator makes; one seed and these settings fix every byte.
struct TerrainSettings {
  std::uint64_t seed = 1;
  double size_m = 48.0; ///< east-west side of the terrain, centred on the origin
  /// North-south side; 0 makes the terrain a square of side size_m. Courses are long strips.
  double width_m = 0.0;
  double cell_m = 0.02;            ///< grid spacing (cm-scale heights)
  double rock_cover = 0.10;        ///< fraction of the ground covered by rocks (0..0.5)
  double crater_density = 0.004;   ///< craters and pits per square metre
  double undulation_m = 0.15;      ///< amplitude of the gentle regolith undulation
  double regional_slope_deg = 2.0; ///< tilt of the whole site
  /// A clear disc around the origin where the rover starts (no rocks, no craters).
  double clear_radius_m = 1.5;
  /// Centre of that disc (a course starts away from the site's centre).
  Eigen::Vector2d clear_centre = Eigen::Vector2d::Zero();
};

/// Throws std::invalid_argument naming the first setting out of range: size, width (or 0) and
/// cell must be positive with 2..16384 nodes a side, rock_cover in [0, 0.5], crater_density in [0,
/// 1], undulation_m in [0, 10], regional_slope_deg in [0, 45), clear_radius_m >= 0.
void validate(const TerrainSettings& settings);

/// The north-south side: width_m, or size_m for a square.
inline double north_south_m(const TerrainSettings& settings) {
  return settings.width_m > 0.0 ? settings.width_m : settings.size_m;
}

/// A generated site: heights, surface albedo (0..1 per node) and the ground-truth obstacle map
/// (255 where the rover's locomotion limits forbid standing or crossing).
struct Terrain {
  TerrainSettings settings;
  HeightField height;
  imaging::Image<float> albedo;
  imaging::Image<std::uint8_t> obstacles;

  /// round(size_m / cell_m) by round(width / cell_m) nodes centred on the origin: regolith
  /// undulation, regional slope and roughness, then craters and pits, the regolith albedo, rocks
  /// (heights and albedo), and the obstacle map (docs/world.md). Byte-identical for identical
  /// settings; throws std::invalid_argument for bad settings or limits (see validate()).
  static Terrain generate(const TerrainSettings& settings, const LocomotionLimits& limits = {});
};

} // namespace marsokhod::world
