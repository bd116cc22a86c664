// UpsetExposure: what an upset rate makes of a campaign's unsafe share over a year.
#pragma once

#include "marsokhod/eval/faults/campaign_tally.hpp"
#include "marsokhod/eval/faults/wilson_interval.hpp"

#include <cstdint>

namespace marsokhod::eval {

/// Days in the year the exposure is counted over (a Julian year).
inline constexpr double kDaysPerYear = 365.25;

/// The unsafe outcomes a year of operations would see at an upset rate: each run holds one
/// upset, drawn over every bit the rate strikes, so the unsafe share of the judged runs is the
/// chance that one upset makes its cycle unsafe, and the year brings rate x bits x kDaysPerYear
/// of them (while upsets are rare enough that a cycle sees at most one).
struct UpsetExposure {
  double upsets_per_day = 0.0;
  double expected_unsafe_per_year = 0.0;
  Interval expected_unsafe_per_year_ci95; ///< the Wilson interval of the unsafe share, scaled
};

/// The exposure at `rate_per_bit_day` upsets per bit per day over `memory_bits` bits.
UpsetExposure upset_exposure(double rate_per_bit_day, std::uint64_t memory_bits,
                             const CampaignTally& tally);

} // namespace marsokhod::eval
