// The summary of a campaign in Markdown.

#include "faults/campaign_report.hpp"

#include "marsokhod/eval/campaign/campaign_summary.hpp"
#include "marsokhod/eval/faults/upset_exposure.hpp"
#include "marsokhod/eval/faults/wilson_interval.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace marsokhod::apps {
namespace {

using eval::fraction;

/// A table in Markdown: one row per entry, one column per outcome class.
std::string table_markdown(const std::string& first_column,
                           const std::map<std::string, eval::OutcomeCounts>& table) {
  std::string md = fmt::format("| {} |", first_column);
  for (const eval::Outcome outcome : eval::kOutcomes)
    md += fmt::format(" {} |", eval::to_string(outcome));
  md += "\n|---|";
  for (std::size_t i = 0; i < eval::kOutcomes.size(); ++i)
    md += "---|";
  md += "\n";
  for (const auto& [name, counts] : table) {
    md += fmt::format("| {} |", name);
    for (const eval::Outcome outcome : eval::kOutcomes)
      md += fmt::format(" {} |", counts[outcome]);
    md += "\n";
  }
  md += '\n';
  return md;
}

std::string protection_line(const overswitch::CampaignSpec& spec,
                            const eval::CampaignFacts& facts) {
  const overswitch::Protection& p = spec.protection;
  return fmt::format(
      "- protection: EDAC {}{}, link checksums {}, terrain check {}; the fault-free cycle {:.3f} "
      "s against {:.3f} s unprotected ({:+.2f} %)\n",
      p.edac ? "on" : "off",
      p.scrub_period
          ? fmt::format(" with a scrub every {} s", emulator::to_seconds(*p.scrub_period))
          : "",
      p.link_checksums ? "on" : "off", p.terrain_check ? "on" : "off", facts.cycle_s,
      facts.unprotected_cycle_s, 100.0 * (facts.cycle_s / facts.unprotected_cycle_s - 1.0));
}

std::string exposure_line(const overswitch::UpsetRate& rate, const eval::CampaignFacts& facts,
                          const eval::CampaignTally& t) {
  const eval::UpsetExposure e = eval::upset_exposure(rate.per_bit_per_day, facts.memory_bits, t);
  return fmt::format("- upsets at {:.3g} per bit per day ({}: {}): {:.3g} a day in the {} bits of "
                     "the powered modules; expected unsafe cycles per year of operations {:.3g} "
                     "(95 % {:.3g}..{:.3g})\n",
                     rate.per_bit_per_day, rate.name, rate.source, e.upsets_per_day,
                     facts.memory_bits, e.expected_unsafe_per_year,
                     e.expected_unsafe_per_year_ci95.low, e.expected_unsafe_per_year_ci95.high);
}

} // namespace

std::string summary_markdown(const overswitch::CampaignSpec& spec, const eval::CampaignFacts& facts,
                             const eval::CampaignTally& t, double runs_per_minute) {
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
  const eval::Interval ci = eval::wilson_95(t.unsafe, t.judged);
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
    md += protection_line(spec, facts);
  if (spec.upset_rate)
    md += exposure_line(*spec.upset_rate, facts, t);
  md += '\n';
  md += table_markdown("fault kind", t.by_kind);
  if (t.by_region.empty())
    return md;
  md += table_markdown("memory region", t.by_region);
  md += table_markdown("buffer", t.by_buffer);
  return md;
}

} // namespace marsokhod::apps
