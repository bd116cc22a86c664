// Running a sweep of traverses in worker processes and gathering its figures.
#include "marsokhod/eval/traverse/traverse_sweep.hpp"

#include "marsokhod/eval/campaign/job_pool.hpp"
#include "marsokhod/eval/traverse/traverse_map.hpp"
#include "marsokhod/imaging/image/image_io.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace marsokhod::eval {
namespace {

using json = nlohmann::ordered_json;

constexpr int kMaxJobs = 64;
constexpr std::array kTraverseOutcomes{TraverseOutcome::success, TraverseOutcome::hand_over,
                                       TraverseOutcome::unsafe, TraverseOutcome::timeout};

TraverseSettings trial_settings(const TraverseSweep& sweep, std::uint64_t trial) {
  const std::uint64_t seeds = sweep.last_seed - sweep.first_seed + 1;
  TraverseSettings s = sweep.course;
  s.rocks = sweep.rocks[static_cast<std::size_t>(trial / seeds)];
  s.seed = sweep.first_seed + trial % seeds;
  return s;
}

std::string trial_line(const TraverseSweep& sweep, std::uint64_t trial) {
  const TraverseSettings s = trial_settings(sweep, trial);
  const world::Terrain terrain = world::Terrain::generate(traverse_site(s));
  const TraverseResult r = run_traverse(terrain, s);
  if (!sweep.failed_maps.empty() && r.outcome != TraverseOutcome::success)
    imaging::write_image(sweep.failed_maps / fmt::format("map-k{}-seed{}.png", s.rocks, s.seed),
                         traverse_map(terrain, r).view());
  json line;
  line["trial"] = trial;
  line["seed"] = s.seed;
  line["rocks"] = s.rocks;
  line["outcome"] = std::string(to_string(r.outcome));
  line["distance_m"] = r.distance_m;
  line["path_efficiency"] = r.path_efficiency();
  line["cycles"] = r.cycles.size();
  line["emergency_stops"] = r.emergency_stops;
  line["hand_overs"] = r.hand_overs;
  line["unsafe_events"] = r.unsafe_events.size();
  line["unsafe_why"] = r.unsafe_events.empty() ? "" : r.unsafe_events.front().why;
  line["mission_seconds"] = r.mission_seconds();
  line["driving_seconds"] = r.driving_seconds;
  line["compute_seconds"] = r.compute_seconds;
  line["fault_outcome"] = r.faults.empty() ? "" : r.faults.front().outcome;
  line["fault_time_lost_s"] = r.faults.empty() ? 0.0 : r.faults.front().time_lost_s;
  return line.dump();
}

// Sums of one rock cover's trials.
struct Tally {
  std::map<std::string, std::uint64_t> outcomes;
  double spl = 0.0;
  double distance = 0.0;
  double stops = 0.0;
  double hand_overs = 0.0;
  double mission = 0.0;
  double driving = 0.0;
  std::map<std::string, std::uint64_t> faults; ///< fault outcome -> trials it struck
};

void add_trial(Tally& t, const nlohmann::json& line) {
  const std::string outcome = line.at("outcome").get<std::string>();
  ++t.outcomes[outcome];
  if (outcome == "success")
    t.spl += line.at("path_efficiency").get<double>();
  t.distance += line.at("distance_m").get<double>();
  t.stops += line.at("emergency_stops").get<double>();
  t.hand_overs += line.at("hand_overs").get<double>();
  t.mission += line.at("mission_seconds").get<double>();
  t.driving += line.at("driving_seconds").get<double>();
  if (const std::string fault = line.at("fault_outcome").get<std::string>(); !fault.empty())
    ++t.faults[fault];
}

double per(double count, double per_amount, double amount) {
  return amount > 0.0 ? count * per_amount / amount : 0.0;
}

} // namespace

void validate(const TraverseSweep& sweep) {
  if (sweep.rocks.empty())
    throw std::invalid_argument("traverse sweep: the rock list is empty");
  for (const double k : sweep.rocks)
    if (!(k >= 0.0 && k <= 0.5))
      throw std::invalid_argument(fmt::format("traverse sweep: rocks {} is not within 0..0.5", k));
  if (sweep.last_seed < sweep.first_seed)
    throw std::invalid_argument("traverse sweep: the last seed is below the first");
  if (sweep.jobs < 1 || sweep.jobs > kMaxJobs)
    throw std::invalid_argument(
        fmt::format("traverse sweep: jobs = {} must be within 1..{}", sweep.jobs, kMaxJobs));
  validate(sweep.course);
}

std::uint64_t sweep_trials(const TraverseSweep& sweep) {
  return (sweep.last_seed - sweep.first_seed + 1) * sweep.rocks.size();
}

std::vector<std::string> run_sweep(const TraverseSweep& sweep,
                                   const std::function<void(std::uint64_t)>& progress) {
  validate(sweep);
  return run_in_jobs(
      0, sweep_trials(sweep), sweep.jobs,
      [&sweep](std::uint64_t trial) { return trial_line(sweep, trial); }, progress);
}

std::string sweep_trial_line(const TraverseSweep& sweep, std::uint64_t trial) {
  validate(sweep);
  if (trial >= sweep_trials(sweep))
    throw std::invalid_argument(fmt::format("traverse sweep: trial {} is past the last, {}", trial,
                                            sweep_trials(sweep) - 1));
  return trial_line(sweep, trial);
}

std::vector<RockFigures> sweep_figures(const TraverseSweep& sweep,
                                       const std::vector<std::string>& lines) {
  std::vector<Tally> tallies(sweep.rocks.size());
  const std::uint64_t seeds = sweep.last_seed - sweep.first_seed + 1;
  for (const std::string& text : lines) {
    const nlohmann::json line = nlohmann::json::parse(text);
    add_trial(tallies.at(static_cast<std::size_t>(line.at("trial").get<std::uint64_t>() / seeds)),
              line);
  }
  std::vector<RockFigures> figures;
  for (std::size_t i = 0; i < tallies.size(); ++i) {
    const Tally& t = tallies[i];
    RockFigures f;
    f.rocks = sweep.rocks[i];
    for (const TraverseOutcome o : kTraverseOutcomes) {
      const auto found = t.outcomes.find(std::string(to_string(o)));
      f.outcomes[std::string(to_string(o))] = found == t.outcomes.end() ? 0 : found->second;
      f.trials += f.outcomes[std::string(to_string(o))];
    }
    const std::uint64_t successes = f.outcomes["success"];
    f.success_rate = f.trials > 0 ? static_cast<double>(successes) / f.trials : 0.0;
    f.success_ci95 = wilson_95(successes, f.trials);
    f.spl = f.trials > 0 ? t.spl / f.trials : 0.0;
    f.unsafe_trials = f.outcomes["unsafe"];
    f.emergency_stops_per_100m = per(t.stops, 100.0, t.distance);
    f.hand_overs_per_100m = per(t.hand_overs, 100.0, t.distance);
    f.metres_per_hour = per(t.distance, 3600.0, t.mission);
    f.metres_per_hour_driving = per(t.distance, 3600.0, t.driving);
    f.fault_outcomes = t.faults;
    figures.push_back(f);
  }
  return figures;
}

json sweep_json(const std::vector<RockFigures>& figures) {
  json doc;
  std::uint64_t trials = 0;
  json by_rocks = json::array();
  for (const RockFigures& f : figures) {
    trials += f.trials;
    json outcomes;
    for (const auto& [name, count] : f.outcomes)
      outcomes[name] = count;
    by_rocks.push_back({{"rocks", f.rocks},
                        {"trials", f.trials},
                        {"outcomes", outcomes},
                        {"success_rate", f.success_rate},
                        {"success_ci95", {f.success_ci95.low, f.success_ci95.high}},
                        {"spl", f.spl},
                        {"unsafe_trials", f.unsafe_trials},
                        {"emergency_stops_per_100m", f.emergency_stops_per_100m},
                        {"hand_overs_per_100m", f.hand_overs_per_100m},
                        {"metres_per_hour", f.metres_per_hour},
                        {"metres_per_hour_driving", f.metres_per_hour_driving},
                        {"fault_outcomes", f.fault_outcomes}});
  }
  doc["trials"] = trials;
  doc["by_rocks"] = by_rocks;
  return doc;
}

} // namespace marsokhod::eval
