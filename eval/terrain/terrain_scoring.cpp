// Per-pixel scoring of zones, hazards and elevations by true range band, and unsafe paths.
#include "marsokhod/eval/terrain/terrain_scoring.hpp"

#include "marsokhod/nav/path/start_approach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace marsokhod::eval {
namespace {

std::optional<std::size_t> band_of(double range) {
  for (std::size_t i = 0; i < kTerrainBands.size(); ++i)
    if (range >= kTerrainBands[i].from_m && range < kTerrainBands[i].to_m)
      return i;
  return std::nullopt;
}

} // namespace

BandCounts& BandCounts::operator+=(const BandCounts& other) {
  obstacle_pixels += other.obstacle_pixels;
  obstacles_prohibited += other.obstacles_prohibited;
  free_pixels += other.free_pixels;
  free_prohibited += other.free_prohibited;
  for (std::size_t z = 0; z < free_prohibited_as.size(); ++z)
    free_prohibited_as[z] += other.free_prohibited_as[z];
  return *this;
}

namespace {

// Calls score(x, y, counts) for every pixel of the zone map that both cameras see, with the
// counts of its true range band; pixels outside every band are left out.
template <class Score>
BandTable score_bands(const nav::ZoneMap& zones, const world::GroundTruth& truth, Score score) {
  BandTable table{};
  for (int y = 0; y < zones.height(); ++y)
    for (int x = 0; x < zones.width(); ++x) {
      const std::optional<std::size_t> band = band_of(truth.range(x, y));
      if (truth.valid(x, y) == 0 || !band)
        continue;
      score(x, y, table[*band]);
    }
  return table;
}

} // namespace

BandTable score_zones(const nav::ZoneMap& zones, const nav::ZoneMap& truth_zones,
                      const world::GroundTruth& truth) {
  return score_bands(
      zones, truth,
      [&](int x, int y, BandCounts& counts) {
        const bool prohibited = !zones.traversable(x, y);
        if (truth.obstacles(x, y) != 0) {
          ++counts.obstacle_pixels;
          counts.obstacles_prohibited += prohibited ? 1 : 0;
        } else if (truth_zones.traversable(x, y)) {
          ++counts.free_pixels;
          counts.free_prohibited += prohibited ? 1 : 0;
          counts.free_prohibited_as[zones.zone(x, y) % nav::kZoneKinds] += prohibited ? 1 : 0;
        }
      });
}

BandTable score_hazards(const nav::ZoneMap& zones, const world::GroundTruth& truth) {
  return score_bands(
      zones, truth,
      [&](int x, int y, BandCounts& counts) {
        const bool hazard = zones.hazard(x, y);
        if (truth.obstacles(x, y) != 0) {
          ++counts.obstacle_pixels;
          counts.obstacles_prohibited += hazard ? 1 : 0;
        } else {
          ++counts.free_pixels;
          counts.free_prohibited += hazard ? 1 : 0;
        }
      });
}

nav::ZoneMap ground_truth_zones(const nav::TerrainPoints& terrain, const world::GroundTruth& truth,
                                const nav::ZoneOptions& options) {
  nav::ZoneMap zones{imaging::Image<std::uint8_t>(terrain.width(), terrain.height()), {}};
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width(); ++x) {
      nav::Zone zone = nav::Zone::traversable;
      if (truth.valid(x, y) == 0 || !terrain.known(x, y))
        zone = nav::Zone::unknown;
      else if (truth.obstacles(x, y) != 0)
        zone = nav::Zone::step;
      zones.zone(x, y) = static_cast<std::uint8_t>(zone);
    }
  nav::add_margin(terrain, options, zones);
  return zones;
}

void collect_elevation_errors(const nav::TerrainPoints& terrain, const nav::ZoneMap& zones,
                              const world::GroundTruth& truth,
                              std::array<std::vector<float>, kTerrainBands.size()>& errors) {
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width(); ++x) {
      const std::optional<std::size_t> band = band_of(truth.range(x, y));
      if (!band || truth.valid(x, y) == 0 || truth.obstacles(x, y) != 0 || !terrain.known(x, y) ||
          zones.at(x, y) == nav::Zone::unknown)
        continue;
      errors[*band].push_back(std::abs(terrain.elevation(x, y) - truth.elevation(x, y)));
    }
}

bool crosses_obstacle(const nav::PathPlan& plan, const nav::TerrainPoints& truth_terrain,
                      const world::GroundTruth& truth) {
  const auto sees_obstacle = [&truth](const nav::PixelPoint& pixel) {
    return truth.obstacles(pixel.x, pixel.y) != 0;
  };
  if (std::any_of(plan.pixels.begin(), plan.pixels.end(), sees_obstacle))
    return true;
  const std::pmr::vector<nav::PixelPoint> approach = nav::start_approach(truth_terrain, plan.start);
  return std::any_of(approach.begin(), approach.end(), sees_obstacle);
}

double percent(std::uint64_t part, std::uint64_t whole) {
  if (whole == 0)
    return std::numeric_limits<double>::quiet_NaN();
  return 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

} // namespace marsokhod::eval
