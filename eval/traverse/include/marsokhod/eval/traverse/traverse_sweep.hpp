// A sweep of traverses over seeds and rock covers: trials in parallel, success rates with their
// intervals, and what stopped the rover per 100 m.
#pragma once

#include "marsokhod/eval/faults/wilson_interval.hpp"
#include "marsokhod/eval/traverse/traverse.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// What a sweep runs: every seed of [first_seed, last_seed] at every rock cover, the other
/// settings from `course` (its seed and rocks are replaced per trial).
struct TraverseSweep {
  std::uint64_t first_seed = 1;
  std::uint64_t last_seed = 10;
  std::vector<double> rocks{0.0, 0.05, 0.10};
  TraverseSettings course;
  int jobs = 1;
  /// When set, the map of every trial that did not succeed goes here as
  /// map-k<rocks>-seed<seed>.png.
  std::filesystem::path failed_maps;
};

/// Throws std::invalid_argument for an empty or out-of-range rock list, jobs outside 1..64 or
/// a bad course.
void validate(const TraverseSweep& sweep);

/// Trial k of the sweep: rocks[k / seeds], seed first_seed + k % seeds.
std::uint64_t sweep_trials(const TraverseSweep& sweep);

/// Runs every trial in `jobs` worker processes and returns one JSON line per trial in trial
/// order (the same bytes for any jobs): trial, seed, rocks, outcome, distance_m,
/// path_efficiency, cycles, emergency_stops, hand_overs, unsafe_events, mission_seconds,
/// driving_seconds, compute_seconds. `progress(done)` as trials finish.
std::vector<std::string> run_sweep(const TraverseSweep& sweep,
                                   const std::function<void(std::uint64_t)>& progress);

/// Trial `trial` alone (< sweep_trials): the same line run_sweep writes for it.
std::string sweep_trial_line(const TraverseSweep& sweep, std::uint64_t trial);

/// The figures of one rock cover.
struct RockFigures {
  double rocks = 0.0;
  std::uint64_t trials = 0;
  std::map<std::string, std::uint64_t> outcomes; ///< class -> count, every class listed
  double success_rate = 0.0;
  Interval success_ci95;
  double spl = 0.0; ///< mean over trials of success x path efficiency
  std::uint64_t unsafe_trials = 0;
  double emergency_stops_per_100m = 0.0;
  double hand_overs_per_100m = 0.0;
  double metres_per_hour = 0.0;         ///< distance over mission time
  double metres_per_hour_driving = 0.0; ///< distance over driving time alone
  /// The outcome classes of the emulated computer's faults (docs/faults.md) over the trials
  /// one struck (--faults).
  std::map<std::string, std::uint64_t> fault_outcomes;
};

/// The figures per rock cover, in the order of the sweep's list, from the trial lines.
std::vector<RockFigures> sweep_figures(const TraverseSweep& sweep,
                                       const std::vector<std::string>& lines);

/// summary.json's figures (trials, by_rocks); the caller adds host values.
nlohmann::ordered_json sweep_json(const std::vector<RockFigures>& figures);

} // namespace marsokhod::eval
