// The figures of an evaluation on synthetic terrain, aggregated over its seeds.
#pragma once

#include "marsokhod/eval/terrain/terrain_evaluation.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// The figures of one range band; percentages and errors are NaN where nothing was scored.
struct BandFigures {
  std::string band_m; ///< "2-6"
  std::uint64_t obstacle_pixels = 0;
  double obstacle_recall = 0.0; ///< % of obstacle pixels prohibited
  std::uint64_t free_pixels = 0;
  double false_prohibited = 0.0; ///< % of free pixels prohibited
  double hazard_recall = 0.0;    ///< % of obstacle pixels the hazards alone catch
  double false_hazard = 0.0;     ///< % of free pixels the hazards alone prohibit
  /// Elevation error on judged free ground, centimetres: median, 90 % and 99 % quantiles.
  std::array<double, 3> elevation_error_cm{};
};

/// Every figure `eval terrain` reports; percentages are NaN where nothing was scored.
struct TerrainFigures {
  std::size_t seeds = 0;
  double obstacle_recall = 0.0;  ///< 2-10 m
  double false_prohibited = 0.0; ///< 2-10 m
  /// 2-10 m false prohibition split by the zone the navigation gave (nav::Zone order; the
  /// traversable entry is unused).
  std::array<double, nav::kZoneKinds> false_prohibited_by_zone{};
  int paths_found = 0;
  int ground_truth_paths = 0;
  int paths_found_where_ground_truth_has_one = 0;
  int unsafe_paths = 0;            ///< by the footprint judge
  int unsafe_paths_pixel_rule = 0; ///< by the old one-pixel line rule, for comparison
  double navigation_seconds_per_seed = 0.0;
  double navigation_ms_per_seed = 0.0;
  std::array<BandFigures, kTerrainBands.size()> bands{};
};

/// Aggregates the outcomes of every seed into the reported figures.
TerrainFigures terrain_figures(const std::vector<SeedOutcome>& outcomes);

/// The q-quantile (0..1) of `values`, NaN when empty; reorders `values`.
double quantile(std::vector<float>& values, double q);

/// "2-6" for the band from 2 to 6 m.
std::string band_name(const RangeBand& band);

} // namespace marsokhod::eval
