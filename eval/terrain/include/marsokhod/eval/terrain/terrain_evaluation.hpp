// Evaluation on synthetic terrain: per seed, render a site, navigate on it and score the result.
#pragma once

#include "marsokhod/eval/terrain/terrain_scoring.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// The seeds to evaluate, both ends included.
struct SeedRange {
  std::uint64_t first = 0;
  std::uint64_t last = 0;
};

/// Reads "A..B" or a single seed "A"; throws OptionError quoting the text when it is malformed,
/// runs backwards or spans more than 10000 seeds.
SeedRange parse_seed_range(const std::string& text);

/// How each site is built and navigated.
struct TerrainEvaluationOptions {
  int size = 256;                 ///< image width and height, pixels
  std::string light = "high-sun"; ///< lighting preset name
  double rocks = world::TerrainSettings{}.rock_cover;
  double terrain_size = world::TerrainSettings{}.size_m;
  bool oracle = false;  ///< navigate on the ground-truth disparity instead of matching
  std::string pictures; ///< folder for one comparison picture per seed, empty for none
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
  bool unsafe = false;
  ElevationErrors elevation_errors{};
  std::string reason;
  double seconds = 0.0; ///< navigation only, host wall clock
};

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
