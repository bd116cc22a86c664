// A campaign's summary: outcome counts by class and fault kind, the unsafe rate with its
// Wilson interval, detection; as JSON, Markdown and charts.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/overswitch/campaign_file.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace marsokhod::apps {

/// The 95 % Wilson score interval of `successes` in `trials` (Wilson 1927); [0, 1] for none.
struct Interval {
  double low = 0.0;
  double high = 1.0;
};
Interval wilson_95(std::uint64_t successes, std::uint64_t trials);

/// Counts over the run records (runs.jsonl lines, parsed).
struct CampaignTally {
  std::uint64_t runs = 0;
  /// Runs of a scene whose fault-free path is unsafe: the navigation's own error, so they are
  /// left out of the unsafe rate (a fault can never be blamed for it there).
  std::uint64_t golden_unsafe_runs = 0;
  std::uint64_t judged = 0; ///< the others: what the unsafe rate is over
  std::uint64_t unsafe = 0;
  std::uint64_t activated = 0; ///< runs whose fault stopped a module (FaultVerdict::activated)
  std::uint64_t detected = 0;
  std::map<std::string, std::uint64_t> outcomes;
  std::map<std::string, std::map<std::string, std::uint64_t>> by_kind;
  std::vector<double> detection_latency_s;
  std::uint64_t telemetry_lost = 0;
  std::uint64_t wheels_commanded_while_failed = 0;
  std::uint64_t path_equals_golden = 0;
};

CampaignTally tally(const std::vector<nlohmann::json>& records);

/// summary.json: runs, runs_per_minute, outcomes, by_kind, unsafe_rate, unsafe_ci95,
/// detected_fraction and the rest.
nlohmann::ordered_json summary_json(const overswitch::CampaignSpec& spec, const CampaignTally& t,
                                    double runs_per_minute);
std::string summary_markdown(const overswitch::CampaignSpec& spec, const CampaignTally& t,
                             double runs_per_minute);
imaging::Image<std::uint8_t> outcomes_chart(const CampaignTally& t);
imaging::Image<std::uint8_t> latency_chart(const CampaignTally& t);

} // namespace marsokhod::apps
