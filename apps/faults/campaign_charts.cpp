// The campaign's charts: outcomes by fault kind, by memory region and buffer, and the detection
// latency.

#include "faults/campaign_report.hpp"

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace marsokhod::apps {
namespace {

using eval::kOutcomes;
using eval::OutcomeCounts;

/// At most this many bars in a chart by buffer: the most struck, the rest summed as "other".
constexpr std::size_t kMostStruck = 10;

} // namespace

imaging::Image<std::uint8_t> outcomes_chart(const eval::CampaignTally& t) {
  imaging::BarChart chart;
  chart.title = "Outcomes by fault kind";
  chart.y_label = "runs";
  chart.value_format = "{:.0f}";
  for (const auto& [kind, counts] : t.by_kind)
    chart.series.push_back(kind);
  for (const eval::Outcome outcome : kOutcomes) {
    imaging::BarChart::Group group{eval::to_string(outcome), {}};
    for (const auto& [kind, counts] : t.by_kind)
      group.values.push_back(static_cast<double>(counts[outcome]));
    chart.groups.push_back(std::move(group));
  }
  return imaging::draw_bar_chart(chart);
}

// Bins of 10 ms from the fastest detection to the slowest.
imaging::Image<std::uint8_t> latency_chart(const eval::CampaignTally& t) {
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

imaging::Image<std::uint8_t> memory_chart(const std::map<std::string, OutcomeCounts>& by,
                                          const std::string& title) {
  std::vector<std::pair<std::string, OutcomeCounts>> rows(by.begin(), by.end());
  std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return a.second.total() > b.second.total();
  });
  if (rows.size() > kMostStruck) {
    OutcomeCounts other;
    for (std::size_t i = kMostStruck - 1; i < rows.size(); ++i)
      other += rows[i].second;
    rows.resize(kMostStruck - 1);
    rows.emplace_back("other", other);
  }
  imaging::BarChart chart;
  chart.title = title;
  chart.y_label = "runs";
  chart.value_format = "{:.0f}";
  for (const eval::Outcome outcome : kOutcomes)
    chart.series.push_back(eval::to_string(outcome));
  for (const auto& [name, counts] : rows) {
    imaging::BarChart::Group group{name, {}};
    for (const eval::Outcome outcome : kOutcomes)
      group.values.push_back(static_cast<double>(counts[outcome]));
    chart.groups.push_back(std::move(group));
  }
  if (chart.groups.empty())
    chart.groups.push_back(
        {"no memory faults", std::vector<std::optional<double>>(kOutcomes.size(), 0.0)});
  return imaging::draw_bar_chart(chart);
}

} // namespace marsokhod::apps
