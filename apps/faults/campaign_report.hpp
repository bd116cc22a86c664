// A campaign's summary for people: Markdown, and charts of outcomes by fault kind, memory region
// and buffer, and of the detection latency.
#pragma once

#include "marsokhod/eval/campaign/campaign_runner.hpp"
#include "marsokhod/eval/faults/campaign_tally.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <cstdint>
#include <map>
#include <string>

namespace marsokhod::apps {

/// summary.md: the campaign, its counts and rates, and a table by fault kind (and by memory
/// region and buffer).
std::string summary_markdown(const overswitch::CampaignSpec& spec, const eval::CampaignFacts& facts,
                             const eval::CampaignTally& t, double runs_per_minute);

/// Outcomes by fault kind, stacked by class.
imaging::Image<std::uint8_t> outcomes_chart(const eval::CampaignTally& t);
/// Outcomes of the memory faults by region and by buffer (the most struck first).
imaging::Image<std::uint8_t> memory_chart(const std::map<std::string, eval::OutcomeCounts>& by,
                                          const std::string& title);
imaging::Image<std::uint8_t> latency_chart(const eval::CampaignTally& t);

} // namespace marsokhod::apps
