// The 95 % Wilson score interval of a proportion.
#pragma once

#include <cstdint>

namespace marsokhod::eval {

/// A closed interval of a proportion.
struct Interval {
  double low = 0.0;
  double high = 1.0;
};

/// The 95 % Wilson score interval of `successes` in `trials` (Wilson 1927, with z the normal
/// distribution's 97.5 % quantile); [0, 1] when there are no trials.
Interval wilson_95(std::uint64_t successes, std::uint64_t trials);

} // namespace marsokhod::eval
