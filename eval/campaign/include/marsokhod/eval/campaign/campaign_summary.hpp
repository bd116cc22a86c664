// A campaign's summary: its counts, rates and intervals as summary.json gives them.
#pragma once

#include "marsokhod/eval/campaign/campaign_runner.hpp"
#include "marsokhod/eval/faults/campaign_tally.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <nlohmann/json.hpp>

#include <array>

namespace marsokhod::eval {

/// The upset rates, per bit per day, a summary gives the year's exposure at beside the
/// campaign's own: 1e-9 .. 1e-6, the span of docs/faults.md's presets.
inline constexpr std::array<double, 7> kSweptUpsetRates{1e-9, 3e-9, 1e-8, 3e-8, 1e-7, 3e-7, 1e-6};

/// The fraction part / whole, 0 for no whole.
double fraction(std::uint64_t part, std::uint64_t whole);

/// The counts as a JSON object of the classes that occur, in kOutcomes order.
nlohmann::ordered_json outcome_counts_json(const OutcomeCounts& counts);

/// summary.json: runs, runs_per_minute, outcomes, by_kind (by_region, by_buffer), unsafe_rate
/// and unsafe_ci95, detection, protection and its cost, and with an upset rate the year's
/// expected unsafe cycles (docs/faults.md, "Campaigns").
nlohmann::ordered_json summary_json(const overswitch::CampaignSpec& spec,
                                    const CampaignFacts& facts, const CampaignTally& tally,
                                    double runs_per_minute);

} // namespace marsokhod::eval
