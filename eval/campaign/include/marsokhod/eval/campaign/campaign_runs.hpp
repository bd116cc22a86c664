// Making a campaign's runs in worker processes until its stopping rule holds.
#pragma once

#include "marsokhod/eval/campaign/campaign_runner.hpp"
#include "marsokhod/eval/faults/campaign_tally.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// How a campaign's runs are made.
struct RunPlan {
  std::uint64_t runs = 0; ///< at most
  int jobs = 1;           ///< worker processes
  bool skip = true;       ///< judge the runs their fault cannot change without emulating them
  /// The stopping rule: stop once the unsafe rate's 95 % interval is no wider than this.
  std::optional<double> ci_width;
};

/// Runs between two looks at the stopping rule. Fixed, so that the runs made do not depend on
/// the number of jobs.
inline constexpr std::uint64_t kStoppingRuleBatch = 500;

/// The stopping rule: the unsafe rate's 95 % Wilson interval over the judged runs is no wider
/// than `ci_width`.
bool interval_narrow_enough(const CampaignTally& tally, double ci_width);

/// A campaign's runs, in run order: their lines of runs.jsonl as the workers wrote them and the
/// records they hold.
struct CampaignRuns {
  std::vector<std::string> lines;
  std::vector<RunRecord> records;
};

/// Runs 0, 1, ... in `plan.jobs` workers: all `plan.runs`, or with a stopping rule batch by
/// batch until it holds. `progress(done)` (may be empty) is told the runs done so far.
CampaignRuns make_runs(const CampaignRunner& runner, const RunPlan& plan,
                       const std::function<void(std::uint64_t done)>& progress);

} // namespace marsokhod::eval
