// Scoring one synthetic site: zones, hazards, elevation and path against the world's ground truth.
#pragma once

#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/world/render/ground_truth.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// Ground distances over which the hazard detector is scored, metres.
struct RangeBand {
  double from_m = 0.0;
  double to_m = 0.0;
};

/// The bands every figure is given in, nearest first.
inline constexpr std::array<RangeBand, 3> kTerrainBands{{{2.0, 6.0}, {6.0, 10.0}, {10.0, 14.0}}};

/// Pixel counts of one band: ground-truth obstacles and how many of them the navigation
/// prohibited, free ground and how much of it the navigation prohibited anyway.
struct BandCounts {
  std::uint64_t obstacle_pixels = 0;
  std::uint64_t obstacles_prohibited = 0;
  std::uint64_t free_pixels = 0;
  std::uint64_t free_prohibited = 0;
  /// free_prohibited split by the zone the navigation gave those pixels (nav::Zone order).
  std::array<std::uint64_t, nav::kZoneKinds> free_prohibited_as{};

  BandCounts& operator+=(const BandCounts& other);
};

/// The counts of every band, in kTerrainBands order.
using BandTable = std::array<BandCounts, kTerrainBands.size()>;

/// Scores the prohibited zones (hazards and the rover's margin: everything the planner may not
/// cross) against the zones ground truth implies (`truth_zones`, from ground_truth_zones),
/// over the pixels both cameras see (ground truth `valid`: stereo cannot know the others), by
/// the true ground range: an obstacle pixel is a ground-truth
/// obstacle, a free pixel one that ground truth leaves traversable (outside every obstacle's
/// margin too).
BandTable score_zones(const nav::ZoneMap& zones, const nav::ZoneMap& truth_zones,
                      const world::GroundTruth& truth);

/// The detector alone: hazards (unknown, step, slope; no margin) against the ground-truth
/// obstacles, every other visible pixel counting as free.
BandTable score_hazards(const nav::ZoneMap& zones, const world::GroundTruth& truth);

/// The zones ground truth implies: unknown where the two cameras do not both see the point
/// (ground truth `valid`: no stereo pair can know what one camera alone sees, so a path through
/// it is no path the rover could have found), step where the seen point
/// is on an obstacle, then the rover's margin as the navigation adds it.
nav::ZoneMap ground_truth_zones(const nav::TerrainPoints& terrain, const world::GroundTruth& truth,
                                const nav::ZoneOptions& options);

/// Elevation errors (|ours - truth|, metres) per band over the pixels both cameras see on free
/// ground (no obstacle) where the navigation has a point that its zone rules judged (not
/// unknown), appended to `errors`.
void collect_elevation_errors(const nav::TerrainPoints& terrain, const nav::ZoneMap& zones,
                              const world::GroundTruth& truth,
                              std::array<std::vector<float>, kTerrainBands.size()>& errors);

/// True when a pixel of the path sees a ground-truth obstacle, or a pixel of the straight
/// approach from the rover to the path's start, placed on the true terrain, does.
bool crosses_obstacle(const nav::PathPlan& plan, const nav::TerrainPoints& truth_terrain,
                      const world::GroundTruth& truth);

/// Share in percent, absent (NaN) for an empty denominator.
double percent(std::uint64_t part, std::uint64_t whole);

} // namespace marsokhod::eval
