// Evaluation on synthetic terrain: per seed, render a site, navigate on it and score the result.
#pragma once

#include "marsokhod/eval/terrain/footprint_judge.hpp"
#include "marsokhod/eval/terrain/terrain_scoring.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/nav/cycle/checked_path.hpp"
#include "marsokhod/nav/path/path_planner.hpp"
#include "marsokhod/nav/zones/zones.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// The seeds to evaluate, both ends included.
struct SeedRange {
  std::uint64_t first = 0;
  std::uint64_t last = 0;
};

/// Reads "A..B" or a single seed "A"; throws OptionError quoting the text when it is malformed,
/// runs backwards or spans more than `max_seeds` seeds.
SeedRange parse_seed_range(const std::string& text, std::uint64_t max_seeds = 10000);

/// How each site is built and navigated.
struct TerrainEvaluationOptions {
  int size = 256;                 ///< image width and height, pixels
  std::string light = "high-sun"; ///< lighting preset name
  double rocks = world::TerrainSettings{}.rock_cover;
  double terrain_size = world::TerrainSettings{}.size_m;
  bool oracle = false;  ///< navigate on the ground-truth disparity instead of matching
  std::string pictures; ///< folder for one comparison picture per seed, empty for none
  /// The footprint check's grid of seen ground, m (FootprintCheckOptions::unseen_cell_m).
  double unseen_cell_m = nav::FootprintCheckOptions{}.unseen_cell_m;
  /// The zones' step window, m (ZoneOptions::step_baseline_m).
  double step_baseline_m = nav::ZoneOptions{}.step_baseline_m;
  /// The band the path's destination lies in, m (the paper's 10-12 m by default).
  double target_min_m = nav::PlannerOptions{}.target_min_m;
  double target_max_m = nav::PlannerOptions{}.target_max_m;
};

/// Elevation errors per range band, metres.
using ElevationErrors = std::array<std::vector<float>, kTerrainBands.size()>;

/// What one seed's site gave: the zone and hazard counts, the paths and the elevation errors.
struct SeedOutcome {
  std::uint64_t seed = 0;
  BandTable bands{};
  BandTable hazards{};
  bool found = false;
  bool truth_found = false;
  /// The footprint judge's verdict on the drive (footprint_judge.hpp): the rover's whole
  /// footprint, from its centre to the path's end, over a true obstacle.
  bool unsafe = false;
  std::optional<FootprintHit> unsafe_hit; ///< where, when unsafe
  /// The old, kinder rule, kept for comparison: a path pixel (or a pixel of the straight
  /// approach to the start) sees a true obstacle.
  bool unsafe_pixel_rule = false;
  ElevationErrors elevation_errors{};
  std::string reason;
  double seconds = 0.0; ///< navigation only, host wall clock
};

/// How far from the rover's centre the ground must be clear for a single cycle to be judged
/// fairly: the rover stands where it could not have stood among rocks, and the swath it drives
/// first (the chassis' width straight ahead) is hidden from one camera or both up to some
/// distance, ground a rover knows from the cycle before. The radius reaches the far corner of
/// that hidden swath, plus the world's step baseline (obstacle nodes stand that far out from a
/// rock). At least the generator's own clear radius.
double unseen_start_radius(const imaging::StereoRig& rig, const imaging::Chassis& chassis = {});

/// Renders the site of `seed`, navigates on it and scores it; writes seed-N.png into
/// options.pictures when set (throws EvaluationError when the picture cannot be written).
SeedOutcome evaluate_seed(std::uint64_t seed, const TerrainEvaluationOptions& options);

/// Told before each seed: its position (1-based), the number of seeds and the seed itself.
using SeedProgress =
    std::function<void(std::uint64_t position, std::uint64_t count, std::uint64_t seed)>;

/// Creates options.pictures when set (throws std::runtime_error naming it when it cannot be made),
/// then evaluates every seed of the range in order.
std::vector<SeedOutcome> evaluate_seeds(const SeedRange& range,
                                        const TerrainEvaluationOptions& options,
                                        const SeedProgress& progress = {});

} // namespace marsokhod::eval
