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
#include <string_view>

namespace marsokhod::world {
namespace {

void require_range(double value, double lo, double hi, const char* name, const char* range) {
  if (!(value >= lo && value <= hi))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: {} = {} is out of range (must be {})", name, value, range));
}

int nodes_along(double side_m, const TerrainSettings& settings) {
  return static_cast<int>(std::lround(side_m / settings.cell_m));
}

void require_side(double side_m, std::string_view name, const TerrainSettings& settings) {
  if (!(side_m > 0.0) || !std::isfinite(side_m))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: {} = {} must be positive", name, side_m));
  const double nodes = side_m / settings.cell_m;
  if (!(nodes >= 1.5 && nodes < imaging::kMaxImageSide + 0.5))
    throw std::invalid_argument(fmt::format(
        "TerrainSettings: {} / cell_m = {} nodes a side is out of range (must be 2..{})", name,
        nodes, imaging::kMaxImageSide));
}

} // namespace

void validate(const TerrainSettings& settings) {
  if (!(settings.cell_m > 0.0) || !std::isfinite(settings.cell_m))
    throw std::invalid_argument(
        fmt::format("TerrainSettings: cell_m = {} must be positive", settings.cell_m));
  require_side(settings.size_m, "size_m", settings);
  if (settings.width_m != 0.0)
    require_side(settings.width_m, "width_m", settings);
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
  const int nx = nodes_along(settings.size_m, settings);
  const int ny = nodes_along(north_south_m(settings), settings);
  const Eigen::Vector2d half_span = 0.5 * settings.cell_m * Eigen::Vector2d(nx - 1, ny - 1);
  Terrain terrain;
  terrain.settings = settings;
  terrain.height = HeightField(nx, ny, settings.cell_m, -half_span);

  shape_regolith(settings, terrain.height);
  const Eigen::Vector2d extent(settings.size_m, north_south_m(settings));
  const CraterField crater_field{settings.crater_density, extent, settings.clear_radius_m,
                                 settings.clear_centre};
  carve_craters(
      sample_craters(crater_field, terrain_stream_seed(settings.seed, TerrainStream::craters)),
      terrain.height);
  terrain.albedo =
      regolith_albedo(terrain.height, terrain_stream_seed(settings.seed, TerrainStream::albedo));
  const RockField rock_field{settings.rock_cover, extent, settings.clear_radius_m,
                             settings.clear_centre};
  place_rocks(sample_rocks(rock_field, terrain_stream_seed(settings.seed, TerrainStream::rocks)),
              terrain.height, terrain.albedo);
  for (float& a : std::span(terrain.albedo.data(), terrain.albedo.size()))
    a = std::clamp(a, 0.02f, 1.0f);
  terrain.obstacles = obstacle_map(terrain.height, limits);
  return terrain;
}

} // namespace marsokhod::world
