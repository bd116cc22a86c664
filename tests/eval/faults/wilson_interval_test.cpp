// The 95 % Wilson score interval against published values.

#include "marsokhod/eval/faults/wilson_interval.hpp"

#include <gtest/gtest.h>

namespace marsokhod::eval {
namespace {

// Newcombe, "Two-sided confidence intervals for the single proportion: comparison of seven
// methods", Statistics in Medicine 17 (1998) 857-872, Table II, method 3 (the score interval
// without continuity correction), given to four decimals.
TEST(WilsonInterval, MatchesNewcombesWorkedExamples) {
  struct Example {
    std::uint64_t successes;
    std::uint64_t trials;
    double low;
    double high;
  };
  for (const Example& e : {Example{81, 263, 0.2553, 0.3662}, Example{15, 148, 0.0624, 0.1605},
                           Example{0, 20, 0.0, 0.1611}, Example{1, 29, 0.0061, 0.1718}}) {
    const Interval ci = wilson_95(e.successes, e.trials);
    EXPECT_NEAR(ci.low, e.low, 5e-5) << e.successes << " of " << e.trials;
    EXPECT_NEAR(ci.high, e.high, 5e-5) << e.successes << " of " << e.trials;
  }
}

// None of n: the interval is 0 .. z^2 / (n + z^2), with z the normal distribution's 97.5 %
// quantile, 1.959963984540054 (Abramowitz and Stegun, Table 26.5): 3.8415 / (n + 3.8415).
TEST(WilsonInterval, NoneOfNIsZeroToTheClosedForm) {
  const double z2 = 1.959963984540054 * 1.959963984540054;
  for (const std::uint64_t n : {1ULL, 10ULL, 881ULL, 8760ULL, 1'000'000ULL}) {
    const Interval ci = wilson_95(0, n);
    EXPECT_EQ(ci.low, 0.0);
    EXPECT_NEAR(ci.high, z2 / (static_cast<double>(n) + z2), 1e-12 * ci.high) << n;
  }
  // The unprotected cruise campaign's 0 of 881 judged hang-power runs: 0 .. 0.0043.
  EXPECT_NEAR(wilson_95(0, 881).high, 0.0043, 5e-5);
}

TEST(WilsonInterval, AllOfNMirrorsNoneOfN) {
  const Interval none = wilson_95(0, 50);
  const Interval all = wilson_95(50, 50);
  EXPECT_DOUBLE_EQ(all.low, 1.0 - none.high);
  EXPECT_EQ(all.high, 1.0);
}

TEST(WilsonInterval, IsSymmetricAboutOneHalf) {
  const Interval a = wilson_95(3, 40);
  const Interval b = wilson_95(37, 40);
  EXPECT_NEAR(a.low, 1.0 - b.high, 1e-12);
  EXPECT_NEAR(a.high, 1.0 - b.low, 1e-12);
}

TEST(WilsonInterval, NoTrialsSayNothing) {
  const Interval ci = wilson_95(0, 0);
  EXPECT_EQ(ci.low, 0.0);
  EXPECT_EQ(ci.high, 1.0);
}

} // namespace
} // namespace marsokhod::eval
