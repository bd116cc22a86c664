// The summary of a campaign as JSON and Markdown.

#include "campaign_summary.hpp"

#include "marsokhod/emulator/memory/memory_upsets.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace marsokhod::apps {
namespace {

constexpr const auto& kOutcomes = kOutcomeClasses;

double fraction(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

nlohmann::ordered_json counts_json(const OutcomeCounts& counts) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const char* outcome : kOutcomes)
    if (const auto found = counts.find(outcome); found != counts.end())
      j[outcome] = found->second;
  return j;
}

nlohmann::ordered_json table_json(const std::map<std::string, OutcomeCounts>& table) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [name, counts] : table)
    j[name] = counts_json(counts);
  return j;
}

/// The rates a user sweeps over: 1e-9 .. 1e-6 upsets per bit per day.
constexpr std::array<double, 7> kSweptRates{1e-9, 3e-9, 1e-8, 3e-8, 1e-7, 3e-7, 1e-6};

nlohmann::ordered_json protection_json(const overswitch::Protection& p) {
  nlohmann::ordered_json j;
  j["edac"] = p.edac;
  j["scrub_period_s"] = p.scrub_period
                            ? nlohmann::ordered_json(emulator::to_seconds(*p.scrub_period))
                            : nlohmann::ordered_json(nullptr);
  j["link_checksums"] = p.link_checksums;
  j["terrain_check"] = p.terrain_check;
  return j;
}

/// A table in Markdown: one row per entry, one column per outcome class.
std::string table_markdown(const std::string& first_column,
                           const std::map<std::string, OutcomeCounts>& table) {
  std::string md = fmt::format("| {} |", first_column);
  for (const char* outcome : kOutcomes)
    md += fmt::format(" {} |", outcome);
  md += "\n|---|";
  for (std::size_t i = 0; i < kOutcomes.size(); ++i)
    md += "---|";
  md += "\n";
  for (const auto& [name, counts] : table) {
    md += fmt::format("| {} |", name);
    for (const char* outcome : kOutcomes) {
      const auto found = counts.find(outcome);
      md += fmt::format(" {} |", found == counts.end() ? 0 : found->second);
    }
    md += "\n";
  }
  md += '\n';
  return md;
}

} // namespace

nlohmann::ordered_json summary_json(const overswitch::CampaignSpec& spec,
                                    const CampaignFacts& facts, const CampaignTally& t,
                                    double runs_per_minute) {
  nlohmann::ordered_json j;
  j["campaign"] = spec.name;
  j["source"] = spec.source;
  j["platform"] = spec.platform;
  j["seed"] = spec.seed;
  j["runs"] = t.runs;
  j["runs_per_minute"] = runs_per_minute;
  j["skipped_runs"] = facts.skipped_runs;
  j["golden_unsafe_runs"] = t.golden_unsafe_runs;
  j["judged_runs"] = t.judged;
  j["outcomes"] = counts_json(t.outcomes);
  j["by_kind"] = table_json(t.by_kind);
  if (!t.by_region.empty()) {
    j["by_region"] = table_json(t.by_region);
    j["by_buffer"] = table_json(t.by_buffer);
  }
  j["unsafe_rate"] = fraction(t.unsafe, t.judged);
  const Interval ci = wilson_95(t.unsafe, t.judged);
  j["unsafe_ci95"] = {ci.low, ci.high};
  j["activated_runs"] = t.activated;
  j["detected_runs"] = t.detected;
  j["detected_fraction"] = fraction(t.detected_activated, t.activated);
  j["edac_corrected_runs"] = t.edac_corrected;
  j["path_equals_golden_runs"] = t.path_equals_golden;
  j["telemetry_lost_runs"] = t.telemetry_lost;
  j["wheels_commanded_while_failed_runs"] = t.wheels_commanded_while_failed;
  if (!t.detection_latency_s.empty()) {
    const auto [low, high] =
        std::minmax_element(t.detection_latency_s.begin(), t.detection_latency_s.end());
    double sum = 0.0;
    for (const double s : t.detection_latency_s)
      sum += s;
    j["detection_latency_s"] = {{"min", *low},
                                {"mean", sum / static_cast<double>(t.detection_latency_s.size())},
                                {"max", *high}};
  }
  j["protection"] = protection_json(spec.protection);
  j["cycle_s"] = {{"mean", facts.cycle_s},
                  {"mean_unprotected", facts.unprotected_cycle_s},
                  {"protection_cost_fraction", facts.unprotected_cycle_s > 0
                                                   ? facts.cycle_s / facts.unprotected_cycle_s - 1.0
                                                   : 0.0}};
  j["memory_overhead_fraction"] =
      spec.protection.edac ? static_cast<double>(emulator::kEdacCheckBits) / 32.0 : 0.0;
  if (!spec.upset_rate)
    return j;
  const UpsetExposure e = upset_exposure(spec.upset_rate->per_bit_per_day, facts, t);
  j["upset_rate"] = {{"preset", spec.upset_rate->name},
                     {"per_bit_per_day", spec.upset_rate->per_bit_per_day},
                     {"source", spec.upset_rate->source}};
  j["memory_bits"] = facts.memory_bits;
  j["upsets_per_day"] = e.upsets_per_day;
  j["expected_unsafe_per_year"] = e.expected_unsafe_per_year;
  j["expected_unsafe_per_year_ci95"] = {e.expected_unsafe_per_year_ci95.low,
                                        e.expected_unsafe_per_year_ci95.high};
  j["expected_unsafe_per_year_by_rate"] = nlohmann::ordered_json::array();
  for (const double rate : kSweptRates) {
    const UpsetExposure at = upset_exposure(rate, facts, t);
    j["expected_unsafe_per_year_by_rate"].push_back(
        {{"per_bit_per_day", rate},
         {"expected_unsafe_per_year", at.expected_unsafe_per_year},
         {"ci95", {at.expected_unsafe_per_year_ci95.low, at.expected_unsafe_per_year_ci95.high}}});
  }
  return j;
}

std::string summary_markdown(const overswitch::CampaignSpec& spec, const CampaignFacts& facts,
                             const CampaignTally& t, double runs_per_minute) {
  std::string md = fmt::format("# Campaign {}\n\n{}\n\n", spec.name, spec.description);
  md += fmt::format("- platform: {}; world seeds: {}; campaign seed {}\n", spec.platform,
                    fmt::join(spec.world_seeds, ", "), spec.seed);
  md += fmt::format("- runs: {} ({} on scenes whose fault-free path is already unsafe, left out "
                    "of the unsafe rate, so {} judged); {:.0f} runs per minute\n",
                    t.runs, t.golden_unsafe_runs, t.judged, runs_per_minute);
  if (facts.skipped_runs > 0)
    md += fmt::format("- {} runs judged without emulating them: their upset struck free memory or "
                      "was corrected by the EDAC (--no-skip emulates them)\n",
                      facts.skipped_runs);
  const Interval ci = wilson_95(t.unsafe, t.judged);
  md += fmt::format("- unsafe: {} of {} = {:.4f} (95 % Wilson interval {:.4f}..{:.4f})\n", t.unsafe,
                    t.judged, fraction(t.unsafe, t.judged), ci.low, ci.high);
  md += fmt::format("- detected: {} of {} runs whose fault reached the program ({:.1f} %)",
                    t.detected_activated, t.activated,
                    100.0 * fraction(t.detected_activated, t.activated));
  md += t.edac_corrected > 0 ? fmt::format("; {} upsets corrected by the EDAC\n", t.edac_corrected)
                             : "\n";
  md += fmt::format("- the fault-free path in {} runs; telemetry lost in {}; wheels commanded by a "
                    "failed module in {}\n",
                    t.path_equals_golden, t.telemetry_lost, t.wheels_commanded_while_failed);
  if (overswitch::any(spec.protection))
    md += fmt::format("- protection: EDAC {}{}, link checksums {}, terrain check {}; the "
                      "fault-free cycle {:.3f} s against {:.3f} s unprotected ({:+.2f} %)\n",
                      spec.protection.edac ? "on" : "off",
                      spec.protection.scrub_period
                          ? fmt::format(" with a scrub every {} s",
                                        emulator::to_seconds(*spec.protection.scrub_period))
                          : "",
                      spec.protection.link_checksums ? "on" : "off",
                      spec.protection.terrain_check ? "on" : "off", facts.cycle_s,
                      facts.unprotected_cycle_s,
                      100.0 * (facts.cycle_s / facts.unprotected_cycle_s - 1.0));
  if (spec.upset_rate) {
    const UpsetExposure e = upset_exposure(spec.upset_rate->per_bit_per_day, facts, t);
    md += fmt::format("- upsets at {:.3g} per bit per day ({}: {}): {:.3g} a day in the {} bits of "
                      "the powered modules; expected unsafe cycles per year of operations {:.3g} "
                      "(95 % {:.3g}..{:.3g})\n",
                      spec.upset_rate->per_bit_per_day, spec.upset_rate->name,
                      spec.upset_rate->source, e.upsets_per_day, facts.memory_bits,
                      e.expected_unsafe_per_year, e.expected_unsafe_per_year_ci95.low,
                      e.expected_unsafe_per_year_ci95.high);
  }
  md += '\n';
  md += table_markdown("fault kind", t.by_kind);
  if (t.by_region.empty())
    return md;
  md += table_markdown("memory region", t.by_region);
  md += table_markdown("buffer", t.by_buffer);
  return md;
}

} // namespace marsokhod::apps
