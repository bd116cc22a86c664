// The terrain generator: settings checked, then regolith, craters, rocks and obstacles.

#include "marsokhod/world/terrain/craters.hpp"
#include "marsokhod/world/terrain/regolith.hpp"
#include "marsokhod/world/terrain/rocks.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

namespace marsokhod::world {
namespace {

void require_range(double value, double lo, double hi, const char* name, const char* range) {
  if (!(value >= lo && value <= hi))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: {} = {} is out of range (must be {})", name, value, range));
}

int nodes_per_side(const TerrainSettings& settings) {
  return static_cast<int>(std::lround(settings.size_m / settings.cell_m));
}

} // namespace

void validate(const TerrainSettings& settings) {
  if (!(settings.cell_m > 0.0) || !std::isfinite(settings.cell_m))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: cell_m = {} must be positive", settings.cell_m));
  if (!(settings.size_m > 0.0) || !std::isfinite(settings.size_m))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: size_m = {} must be positive", settings.size_m));
  const double nodes = settings.size_m / settings.cell_m;
  if (!(nodes >= 1.5 && nodes < imaging::kMaxImageSide + 0.5))
    throw std::invalid_argument(fmt::format(
        "TerrainSettings: size_m / cell_m = {} nodes a side is out of range (must be 2..{})", nodes,
        imaging::kMaxImageSide));
  require_range(settings.rock_cover, 0.0, 0.5, "rock_cover", "0..0.5");
  require_range(settings.crater_density, 0.0, 1.0, "crater_density", "0..1 per square metre");
  require_range(settings.undulation_m, 0.0, 10.0, "undulation_m", "0..10 m");
  if (!(settings.regional_slope_deg >= 0.0 && settings.regional_slope_deg < 45.0))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: regional_slope_deg = {} is out of range (must be 0 .. <45)",
                    settings.regional_slope_deg));
  if (!settings.clear_centre.allFinite())
    throw std::invalid_argument("TerrainSettings: clear_centre must be finite");
  if (!(settings.clear_radius_m >= 0.0) || !std::isfinite(settings.clear_radius_m))
    throw std::invalid_argument(fmt::format(
        "TerrainSettings: clear_radius_m = {} must be zero or positive", settings.clear_radius_m));
}

Terrain Terrain::generate(const TerrainSettings& settings, const LocomotionLimits& limits) {
  validate(settings);
  validate(limits);
  const int n = nodes_per_side(settings);
  const double half_span = 0.5 * (n - 1) * settings.cell_m;
  Terrain terrain;
  terrain.settings = settings;
  terrain.height = HeightField(n, n, settings.cell_m, Eigen::Vector2d(-half_span, -half_span));

  shape_regolith(settings, terrain.height);
  const CraterField crater_field{settings.crater_density, settings.size_m, settings.clear_radius_m,
                                 settings.clear_centre};
  carve_craters(
      sample_craters(crater_field, terrain_stream_seed(settings.seed, TerrainStream::craters)),
      terrain.height);
  terrain.albedo =
      regolith_albedo(terrain.height, terrain_stream_seed(settings.seed, TerrainStream::albedo));
  const RockField rock_field{settings.rock_cover, settings.size_m, settings.clear_radius_m,
                             settings.clear_centre};
  place_rocks(sample_rocks(rock_field, terrain_stream_seed(settings.seed, TerrainStream::rocks)),
              terrain.height, terrain.albedo);
  for (float& a : std::span(terrain.albedo.data(), terrain.albedo.size()))
    a = std::clamp(a, 0.02f, 1.0f);
  terrain.obstacles = obstacle_map(terrain.height, limits);
  return terrain;
}

} // namespace marsokhod::world
