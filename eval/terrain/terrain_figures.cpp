// Aggregating the outcomes of every seed into the figures `eval terrain` reports.
#include "marsokhod/eval/terrain/terrain_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::eval {
namespace {

struct Summary {
  BandTable bands{};
  BandTable hazards{};
  BandCounts near{}; // 2-10 m
  ElevationErrors elevation_errors{};
  int found = 0;
  int truth_found = 0;
  int found_where_truth = 0;
  int unsafe = 0;
  int unsafe_pixel_rule = 0;
  double seconds = 0.0;
};

Summary summarize(const std::vector<SeedOutcome>& outcomes) {
  Summary s;
  for (const SeedOutcome& o : outcomes) {
    for (std::size_t b = 0; b < s.bands.size(); ++b) {
      s.bands[b] += o.bands[b];
      s.hazards[b] += o.hazards[b];
    }
    s.found += o.found ? 1 : 0;
    s.truth_found += o.truth_found ? 1 : 0;
    s.found_where_truth += (o.found && o.truth_found) ? 1 : 0;
    s.unsafe += o.unsafe ? 1 : 0;
    s.unsafe_pixel_rule += o.unsafe_pixel_rule ? 1 : 0;
    s.seconds += o.seconds;
    for (std::size_t b = 0; b < s.elevation_errors.size(); ++b)
      s.elevation_errors[b].insert(s.elevation_errors[b].end(), o.elevation_errors[b].begin(),
                                   o.elevation_errors[b].end());
  }
  s.near = s.bands[0];
  s.near += s.bands[1];
  return s;
}

BandFigures band_figures(const Summary& s, std::size_t b) {
  BandFigures figures;
  const BandCounts& c = s.bands[b];
  const BandCounts& h = s.hazards[b];
  figures.band_m = band_name(kTerrainBands[b]);
  figures.obstacle_pixels = c.obstacle_pixels;
  figures.obstacle_recall = percent(c.obstacles_prohibited, c.obstacle_pixels);
  figures.free_pixels = c.free_pixels;
  figures.false_prohibited = percent(c.free_prohibited, c.free_pixels);
  figures.hazard_recall = percent(h.obstacles_prohibited, h.obstacle_pixels);
  figures.false_hazard = percent(h.free_prohibited, h.free_pixels);
  std::vector<float> errors = s.elevation_errors[b];
  figures.elevation_error_cm = {100.0 * quantile(errors, 0.5), 100.0 * quantile(errors, 0.9),
                                100.0 * quantile(errors, 0.99)};
  return figures;
}

} // namespace

TerrainFigures terrain_figures(const std::vector<SeedOutcome>& outcomes) {
  const Summary s = summarize(outcomes);
  TerrainFigures figures;
  figures.seeds = outcomes.size();
  figures.obstacle_recall = percent(s.near.obstacles_prohibited, s.near.obstacle_pixels);
  figures.false_prohibited = percent(s.near.free_prohibited, s.near.free_pixels);
  figures.false_prohibited_by_zone[0] = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t z = 1; z < figures.false_prohibited_by_zone.size(); ++z)
    figures.false_prohibited_by_zone[z] = percent(s.near.free_prohibited_as[z], s.near.free_pixels);
  figures.paths_found = s.found;
  figures.ground_truth_paths = s.truth_found;
  figures.paths_found_where_ground_truth_has_one = s.found_where_truth;
  figures.unsafe_paths = s.unsafe;
  figures.unsafe_paths_pixel_rule = s.unsafe_pixel_rule;
  figures.navigation_seconds_per_seed = outcomes.empty() ? 0.0 : s.seconds / outcomes.size();
  figures.navigation_ms_per_seed = outcomes.empty() ? 0.0 : 1000.0 * s.seconds / outcomes.size();
  for (std::size_t b = 0; b < figures.bands.size(); ++b)
    figures.bands[b] = band_figures(s, b);
  return figures;
}

double quantile(std::vector<float>& values, double q) {
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

std::string band_name(const RangeBand& band) {
  return fmt::format("{:g}-{:g}", band.from_m, band.to_m);
}

} // namespace marsokhod::eval
