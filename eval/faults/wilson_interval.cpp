// The Wilson score interval, with its closed forms at the ends.

#include "marsokhod/eval/faults/wilson_interval.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::eval {

Interval wilson_95(std::uint64_t successes, std::uint64_t trials) {
  if (trials == 0)
    return {};
  constexpr double z = 1.959963984540054;
  if (successes == 0 || successes == trials) {
    // The closed forms: the rounding of the general one would leave 1e-17 for 0 out of n.
    constexpr double z2 = z * z;
    const double bound = z2 / (static_cast<double>(trials) + z2);
    return successes == 0 ? Interval{0.0, bound} : Interval{1.0 - bound, 1.0};
  }
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double denominator = 1.0 + z * z / n;
  const double centre = (p + z * z / (2.0 * n)) / denominator;
  const double half = z * std::sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / denominator;
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

} // namespace marsokhod::eval
