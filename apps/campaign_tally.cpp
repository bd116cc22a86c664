// Counting the run records: outcomes by class, fault kind, memory region and buffer; the Wilson
// interval; what an upset rate makes of the unsafe share.

#include "campaign_summary.hpp"

#include <cctype>
#include <cmath>

namespace marsokhod::apps {
namespace {

/// A buffer's name without its size ("left image, 128 rows x 128 px x 1 B" -> "left image"), so
/// that the same buffer at other sizes counts once.
std::string buffer_group(const std::string& buffer) {
  for (std::size_t comma = buffer.rfind(", "); comma != std::string::npos && comma > 0;
       comma = buffer.rfind(", ", comma - 1))
    if (comma + 2 < buffer.size() && std::isdigit(static_cast<unsigned char>(buffer[comma + 2])))
      return buffer.substr(0, comma);
  return buffer;
}

bool flag(const nlohmann::json& record, const char* key) {
  return record.at(key).get<bool>();
}

} // namespace

Interval wilson_95(std::uint64_t successes, std::uint64_t trials) {
  if (trials == 0)
    return {};
  if (successes == 0 || successes == trials) {
    // The closed forms: the rounding of the general one would leave 1e-17 for 0 out of n.
    constexpr double z2 = 1.959963984540054 * 1.959963984540054;
    const double bound = z2 / (static_cast<double>(trials) + z2);
    return successes == 0 ? Interval{0.0, bound} : Interval{1.0 - bound, 1.0};
  }
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
    const nlohmann::json& fault = r.at("fault");
    ++t.outcomes[outcome];
    ++t.by_kind[fault.at("kind").get<std::string>()][outcome];
    if (fault.contains("region")) {
      ++t.by_region[fault.at("region").get<std::string>()][outcome];
      ++t.by_buffer[buffer_group(fault.at("buffer"))][outcome];
      t.edac_corrected += fault.at("edac") == "corrected" ? 1 : 0;
    }
    if (flag(r, "golden_unsafe"))
      ++t.golden_unsafe_runs;
    else
      ++t.judged;
    t.unsafe += outcome == "unsafe" ? 1 : 0;
    const bool activated = flag(r, "activated");
    t.activated += activated ? 1 : 0;
    if (flag(r, "detected")) {
      ++t.detected;
      t.detected_activated += activated ? 1 : 0;
      if (!r.at("detection_latency_s").is_null())
        t.detection_latency_s.push_back(r.at("detection_latency_s").get<double>());
    }
    t.telemetry_lost += flag(r, "telemetry_lost") ? 1 : 0;
    t.wheels_commanded_while_failed += flag(r, "wheels_commanded_while_failed") ? 1 : 0;
    t.path_equals_golden += flag(r, "path_equals_golden") ? 1 : 0;
  }
  return t;
}

UpsetExposure upset_exposure(double rate_per_bit_day, const CampaignFacts& facts,
                             const CampaignTally& t) {
  UpsetExposure e;
  e.upsets_per_day = rate_per_bit_day * static_cast<double>(facts.memory_bits);
  const double per_year = e.upsets_per_day * 365.25;
  const double share = t.judged == 0 ? 0.0 : static_cast<double>(t.unsafe) / t.judged;
  e.expected_unsafe_per_year = per_year * share;
  const Interval ci = wilson_95(t.unsafe, t.judged);
  e.expected_unsafe_per_year_ci95 = {per_year * ci.low, per_year * ci.high};
  return e;
}

} // namespace marsokhod::apps
