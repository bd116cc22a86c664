// The summary of a campaign as JSON.

#include "marsokhod/eval/campaign/campaign_summary.hpp"

#include "marsokhod/emulator/memory/memory_upsets.hpp"
#include "marsokhod/eval/faults/upset_exposure.hpp"
#include "marsokhod/eval/faults/wilson_interval.hpp"

#include <algorithm>

namespace marsokhod::eval {
namespace {

using Json = nlohmann::ordered_json;

Json table_json(const std::map<std::string, OutcomeCounts>& table) {
  Json j = Json::object();
  for (const auto& [name, counts] : table)
    j[name] = outcome_counts_json(counts);
  return j;
}

Json protection_json(const overswitch::Protection& p) {
  Json j;
  j["edac"] = p.edac;
  j["scrub_period_s"] =
      p.scrub_period ? Json(emulator::to_seconds(*p.scrub_period)) : Json(nullptr);
  j["link_checksums"] = p.link_checksums;
  j["terrain_check"] = p.terrain_check;
  return j;
}

Json latency_json(const std::vector<double>& latencies) {
  const auto [low, high] = std::minmax_element(latencies.begin(), latencies.end());
  double sum = 0.0;
  for (const double s : latencies)
    sum += s;
  return {{"min", *low}, {"mean", sum / static_cast<double>(latencies.size())}, {"max", *high}};
}

Json interval_json(const Interval& interval) {
  return {interval.low, interval.high};
}

void add_exposure(Json& j, const overswitch::UpsetRate& rate, const CampaignFacts& facts,
                  const CampaignTally& t) {
  const UpsetExposure e = upset_exposure(rate.per_bit_per_day, facts.memory_bits, t);
  j["upset_rate"] = {
      {"preset", rate.name}, {"per_bit_per_day", rate.per_bit_per_day}, {"source", rate.source}};
  j["memory_bits"] = facts.memory_bits;
  j["upsets_per_day"] = e.upsets_per_day;
  j["expected_unsafe_per_year"] = e.expected_unsafe_per_year;
  j["expected_unsafe_per_year_ci95"] = interval_json(e.expected_unsafe_per_year_ci95);
  j["expected_unsafe_per_year_by_rate"] = Json::array();
  for (const double swept : kSweptUpsetRates) {
    const UpsetExposure at = upset_exposure(swept, facts.memory_bits, t);
    j["expected_unsafe_per_year_by_rate"].push_back(
        {{"per_bit_per_day", swept},
         {"expected_unsafe_per_year", at.expected_unsafe_per_year},
         {"ci95", interval_json(at.expected_unsafe_per_year_ci95)}});
  }
}

} // namespace

double fraction(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

Json outcome_counts_json(const OutcomeCounts& counts) {
  Json j = Json::object();
  for (const Outcome outcome : kOutcomes)
    if (counts[outcome] > 0)
      j[to_string(outcome)] = counts[outcome];
  return j;
}

Json summary_json(const overswitch::CampaignSpec& spec, const CampaignFacts& facts,
                  const CampaignTally& t, double runs_per_minute) {
  Json j;
  j["campaign"] = spec.name;
  j["source"] = spec.source;
  j["platform"] = spec.platform;
  j["seed"] = spec.seed;
  j["runs"] = t.runs;
  j["runs_per_minute"] = runs_per_minute;
  j["skipped_runs"] = facts.skipped_runs;
  j["golden_unsafe_runs"] = t.golden_unsafe_runs;
  j["judged_runs"] = t.judged;
  j["outcomes"] = outcome_counts_json(t.outcomes);
  j["by_kind"] = table_json(t.by_kind);
  if (!t.by_region.empty()) {
    j["by_region"] = table_json(t.by_region);
    j["by_buffer"] = table_json(t.by_buffer);
  }
  j["unsafe_rate"] = fraction(t.unsafe, t.judged);
  j["unsafe_ci95"] = interval_json(wilson_95(t.unsafe, t.judged));
  j["activated_runs"] = t.activated;
  j["detected_runs"] = t.detected;
  j["detected_fraction"] = fraction(t.detected_activated, t.activated);
  j["edac_corrected_runs"] = t.edac_corrected;
  j["path_equals_golden_runs"] = t.path_equals_golden;
  j["telemetry_lost_runs"] = t.telemetry_lost;
  j["wheels_commanded_while_failed_runs"] = t.wheels_commanded_while_failed;
  if (!t.detection_latency_s.empty())
    j["detection_latency_s"] = latency_json(t.detection_latency_s);
  j["protection"] = protection_json(spec.protection);
  j["cycle_s"] = {{"mean", facts.cycle_s},
                  {"mean_unprotected", facts.unprotected_cycle_s},
                  {"protection_cost_fraction", facts.unprotected_cycle_s > 0
                                                   ? facts.cycle_s / facts.unprotected_cycle_s - 1.0
                                                   : 0.0}};
  j["memory_overhead_fraction"] =
      spec.protection.edac ? static_cast<double>(emulator::kEdacCheckBits) / 32.0 : 0.0;
  if (spec.upset_rate)
    add_exposure(j, *spec.upset_rate, facts, t);
  return j;
}

} // namespace marsokhod::eval
