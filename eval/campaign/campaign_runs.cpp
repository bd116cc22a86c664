// The runs made in batches, the stopping rule looked at after each.

#include "marsokhod/eval/campaign/campaign_runs.hpp"

#include "marsokhod/eval/campaign/job_pool.hpp"
#include "marsokhod/eval/faults/wilson_interval.hpp"

#include <algorithm>

namespace marsokhod::eval {

bool interval_narrow_enough(const CampaignTally& tally, double ci_width) {
  const Interval ci = wilson_95(tally.unsafe, tally.judged);
  return ci.high - ci.low <= ci_width;
}

CampaignRuns make_runs(const CampaignRunner& runner, const RunPlan& plan,
                       const std::function<void(std::uint64_t done)>& progress) {
  CampaignRuns made;
  CampaignTally tally;
  while (made.lines.size() < plan.runs) {
    const std::uint64_t first = made.lines.size();
    const std::uint64_t last =
        plan.ci_width ? std::min(plan.runs, first + kStoppingRuleBatch) : plan.runs;
    const std::vector<std::string> batch = run_in_jobs(
        first, last, plan.jobs,
        [&runner, &plan](std::uint64_t k) {
          return run_record_line(runner.run(k, nullptr, plan.skip));
        },
        [&progress, first](std::uint64_t done) {
          if (progress)
            progress(first + done);
        });
    for (const std::string& line : batch) {
      made.records.push_back(parse_run_record(line));
      count_run(tally, made.records.back());
      made.lines.push_back(line);
    }
    if (plan.ci_width && interval_narrow_enough(tally, *plan.ci_width))
      break;
  }
  return made;
}

} // namespace marsokhod::eval
