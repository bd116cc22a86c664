// The year's expected unsafe cycles at an upset rate, with the share's interval scaled.

#include "marsokhod/eval/faults/upset_exposure.hpp"

namespace marsokhod::eval {

UpsetExposure upset_exposure(double rate_per_bit_day, std::uint64_t memory_bits,
                             const CampaignTally& t) {
  UpsetExposure e;
  e.upsets_per_day = rate_per_bit_day * static_cast<double>(memory_bits);
  const double per_year = e.upsets_per_day * kDaysPerYear;
  const double share = t.judged == 0 ? 0.0 : static_cast<double>(t.unsafe) / t.judged;
  e.expected_unsafe_per_year = per_year * share;
  const Interval ci = wilson_95(t.unsafe, t.judged);
  e.expected_unsafe_per_year_ci95 = {per_year * ci.low, per_year * ci.high};
  return e;
}

} // namespace marsokhod::eval
