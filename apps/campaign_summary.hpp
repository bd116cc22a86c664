// A campaign's summary: outcome counts by class and fault kind, the unsafe rate with its
// Wilson interval, detection; as JSON, Markdown and charts.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/overswitch/campaign_file.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// The 95 % Wilson score interval of `successes` in `trials` (Wilson 1927); [0, 1] for none.
struct Interval {
  double low = 0.0;
  double high = 1.0;
};
Interval wilson_95(std::uint64_t successes, std::uint64_t trials);

/// The outcome classes in the order docs/faults.md decides them.
inline constexpr std::array<const char*, 7> kOutcomeClasses{
    "masked", "recovered", "safe_stop", "sdc_safe", "unsafe", "hang", "error"};

/// Outcome class -> runs.
using OutcomeCounts = std::map<std::string, std::uint64_t>;

/// What the summary needs of the campaign besides its records.
struct CampaignFacts {
  /// Bits an upset may strike in the powered modules: their memory, and the EDAC's check bits.
  std::uint64_t memory_bits = 0;
  /// Mean fault-free cycle over the scenes, with the campaign's protection and without it.
  double cycle_s = 0.0;
  double unprotected_cycle_s = 0.0;
  /// Runs judged from the fault-free run without being emulated (CampaignRunner::skippable).
  std::uint64_t skipped_runs = 0;
};

/// Counts over the run records (runs.jsonl lines, parsed).
struct CampaignTally {
  std::uint64_t runs = 0;
  /// Runs of a scene whose fault-free path is unsafe: the navigation's own error, so they are
  /// left out of the unsafe rate (a fault can never be blamed for it there).
  std::uint64_t golden_unsafe_runs = 0;
  std::uint64_t judged = 0; ///< the others: what the unsafe rate is over
  std::uint64_t unsafe = 0;
  /// Runs whose fault reached the program: it stopped a module, or a memory fault reached data
  /// or control state (FaultVerdict::activated).
  std::uint64_t activated = 0;
  std::uint64_t detected = 0;           ///< a watchdog or the EDAC saw the fault
  std::uint64_t detected_activated = 0; ///< of the activated runs
  std::uint64_t edac_corrected = 0;     ///< memory faults the EDAC corrected
  OutcomeCounts outcomes;
  std::map<std::string, OutcomeCounts> by_kind;
  /// Memory faults by memory region ("external", "on-chip", "on-chip reserved") and by buffer
  /// (the block's name without its size: "left image", "workspace of matching", "free").
  std::map<std::string, OutcomeCounts> by_region;
  std::map<std::string, OutcomeCounts> by_buffer;
  std::vector<double> detection_latency_s;
  std::uint64_t telemetry_lost = 0;
  std::uint64_t wheels_commanded_while_failed = 0;
  std::uint64_t path_equals_golden = 0;
};

CampaignTally tally(const std::vector<nlohmann::json>& records);

/// summary.json: runs, runs_per_minute, outcomes, by_kind, unsafe_rate, unsafe_ci95,
/// detected_fraction and the rest.
/// The unsafe outcomes a year of operations would see at the campaign's upset rate: each run
/// holds one upset, drawn over every bit the rate strikes, so the unsafe share of the runs is
/// the chance that one upset makes its cycle unsafe, and the year brings rate x bits x 365.25 of
/// them (while upsets are rare enough that a cycle sees at most one).
struct UpsetExposure {
  double upsets_per_day = 0.0;
  double expected_unsafe_per_year = 0.0;
  Interval expected_unsafe_per_year_ci95;
};
UpsetExposure upset_exposure(double rate_per_bit_day, const CampaignFacts& facts,
                             const CampaignTally& t);

/// summary.json: runs, runs_per_minute, outcomes, by_kind, unsafe_rate, unsafe_ci95,
/// detected_fraction and the rest.
nlohmann::ordered_json summary_json(const overswitch::CampaignSpec& spec,
                                    const CampaignFacts& facts, const CampaignTally& t,
                                    double runs_per_minute);
std::string summary_markdown(const overswitch::CampaignSpec& spec, const CampaignFacts& facts,
                             const CampaignTally& t, double runs_per_minute);

/// Outcomes by fault kind, stacked by class.
imaging::Image<std::uint8_t> outcomes_chart(const CampaignTally& t);
/// Outcomes of the memory faults by region and by buffer (the most struck first).
imaging::Image<std::uint8_t> memory_chart(const std::map<std::string, OutcomeCounts>& by,
                                          const std::string& title);
imaging::Image<std::uint8_t> latency_chart(const CampaignTally& t);

} // namespace marsokhod::apps
