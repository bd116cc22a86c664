// Tallies, the Wilson interval, and the summary's JSON, Markdown and charts.

#include "campaign_summary.hpp"

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace marsokhod::apps {
namespace {

constexpr std::array<const char*, 7> kOutcomes{"masked", "recovered", "safe_stop", "sdc_safe",
                                               "unsafe", "hang",      "error"};

double fraction(std::uint64_t part, std::uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

nlohmann::ordered_json counts_json(const std::map<std::string, std::uint64_t>& counts) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const char* outcome : kOutcomes)
    if (const auto found = counts.find(outcome); found != counts.end())
      j[outcome] = found->second;
  return j;
}

} // namespace

Interval wilson_95(std::uint64_t successes, std::uint64_t trials) {
  if (trials == 0)
    return {};
  constexpr double z = 1.959963984540054;
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double denominator = 1.0 + z * z / n;
  const double centre = (p + z * z / (2.0 * n)) / denominator;
  const double half = z * std::sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / denominator;
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

CampaignTally tally(const std::vector<nlohmann::json>& records) {
  CampaignTally t;
  for (const nlohmann::json& r : records) {
    ++t.runs;
    const std::string outcome = r.at("outcome");
    const std::string kind = r.at("fault").at("kind");
    ++t.outcomes[outcome];
    ++t.by_kind[kind][outcome];
    if (r.at("golden_unsafe").get<bool>())
      ++t.golden_unsafe_runs;
    else
      ++t.judged;
    t.unsafe += outcome == "unsafe" ? 1 : 0;
    t.activated += r.at("activated").get<bool>() ? 1 : 0;
    if (r.at("detected").get<bool>()) {
      ++t.detected;
      t.detection_latency_s.push_back(r.at("detection_latency_s").get<double>());
    }
    t.telemetry_lost += r.at("telemetry_lost").get<bool>() ? 1 : 0;
    t.wheels_commanded_while_failed += r.at("wheels_commanded_while_failed").get<bool>() ? 1 : 0;
    t.path_equals_golden += r.at("path_equals_golden").get<bool>() ? 1 : 0;
  }
  return t;
}

nlohmann::ordered_json summary_json(const overswitch::CampaignSpec& spec, const CampaignTally& t,
                                    double runs_per_minute) {
  nlohmann::ordered_json j;
  j["campaign"] = spec.name;
  j["source"] = spec.source;
  j["platform"] = spec.platform;
  j["seed"] = spec.seed;
  j["runs"] = t.runs;
  j["runs_per_minute"] = runs_per_minute;
  j["golden_unsafe_runs"] = t.golden_unsafe_runs;
  j["judged_runs"] = t.judged;
  j["outcomes"] = counts_json(t.outcomes);
  j["by_kind"] = nlohmann::ordered_json::object();
  for (const auto& [kind, counts] : t.by_kind)
    j["by_kind"][kind] = counts_json(counts);
  j["unsafe_rate"] = fraction(t.unsafe, t.judged);
  const Interval ci = wilson_95(t.unsafe, t.judged);
  j["unsafe_ci95"] = {ci.low, ci.high};
  j["activated_runs"] = t.activated;
  j["detected_fraction"] = fraction(t.detected, t.activated);
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
  return j;
}

std::string summary_markdown(const overswitch::CampaignSpec& spec, const CampaignTally& t,
                             double runs_per_minute) {
  std::string md = fmt::format("# Campaign {}\n\n{}\n\n", spec.name, spec.description);
  md += fmt::format("- platform: {}; world seeds: {}; campaign seed {}\n", spec.platform,
                    fmt::join(spec.world_seeds, ", "), spec.seed);
  md += fmt::format("- runs: {} ({} on scenes whose fault-free path is already unsafe, left out "
                    "of the unsafe rate, so {} judged); {:.0f} runs per minute\n",
                    t.runs, t.golden_unsafe_runs, t.judged, runs_per_minute);
  const Interval ci = wilson_95(t.unsafe, t.judged);
  md += fmt::format("- unsafe: {} of {} = {:.4f} (95 % Wilson interval {:.4f}..{:.4f})\n", t.unsafe,
                    t.judged, fraction(t.unsafe, t.judged), ci.low, ci.high);
  md += fmt::format("- detected: {} of {} runs whose fault stopped a module ({:.1f} %)\n",
                    t.detected, t.activated, 100.0 * fraction(t.detected, t.activated));
  md += fmt::format("- the fault-free path in {} runs; telemetry lost in {}; wheels commanded by a "
                    "failed module in {}\n\n",
                    t.path_equals_golden, t.telemetry_lost, t.wheels_commanded_while_failed);
  md += "| fault kind |";
  for (const char* outcome : kOutcomes)
    md += fmt::format(" {} |", outcome);
  md += "\n|---|";
  for (std::size_t i = 0; i < kOutcomes.size(); ++i)
    md += "---|";
  md += "\n";
  for (const auto& [kind, counts] : t.by_kind) {
    md += fmt::format("| {} |", kind);
    for (const char* outcome : kOutcomes) {
      const auto found = counts.find(outcome);
      md += fmt::format(" {} |", found == counts.end() ? 0 : found->second);
    }
    md += "\n";
  }
  return md;
}

imaging::Image<std::uint8_t> outcomes_chart(const CampaignTally& t) {
  imaging::BarChart chart;
  chart.title = "Outcomes by fault kind";
  chart.y_label = "runs";
  chart.value_format = "{:.0f}";
  for (const auto& [kind, counts] : t.by_kind)
    chart.series.push_back(kind);
  for (const char* outcome : kOutcomes) {
    imaging::BarChart::Group group{outcome, {}};
    for (const auto& [kind, counts] : t.by_kind) {
      const auto found = counts.find(outcome);
      group.values.push_back(static_cast<double>(found == counts.end() ? 0 : found->second));
    }
    chart.groups.push_back(std::move(group));
  }
  return imaging::draw_bar_chart(chart);
}

// Bins of 10 ms from the fastest detection to the slowest.
imaging::Image<std::uint8_t> latency_chart(const CampaignTally& t) {
  imaging::BarChart chart;
  chart.title = "Detection latency";
  chart.y_label = "runs";
  chart.value_format = "{:.0f}";
  chart.series = {"runs"};
  constexpr double kBin = 0.010;
  if (t.detection_latency_s.empty()) {
    chart.groups.push_back({"none detected", {0.0}});
    return imaging::draw_bar_chart(chart);
  }
  const auto [low, high] =
      std::minmax_element(t.detection_latency_s.begin(), t.detection_latency_s.end());
  const auto first = static_cast<long>(std::floor(*low / kBin));
  const auto last = static_cast<long>(std::floor(*high / kBin));
  std::vector<double> counts(static_cast<std::size_t>(last - first + 1), 0.0);
  for (const double s : t.detection_latency_s)
    counts[static_cast<std::size_t>(static_cast<long>(std::floor(s / kBin)) - first)] += 1.0;
  for (std::size_t i = 0; i < counts.size(); ++i)
    chart.groups.push_back(
        {fmt::format("{:.0f} ms", (static_cast<double>(first) + static_cast<double>(i)) * 10.0),
         {counts[i]}});
  return imaging::draw_bar_chart(chart);
}

} // namespace marsokhod::apps
