// Tests: dead-reckoned odometry with wheel slip, against hand arithmetic.

#include "marsokhod/eval/traverse/odometry.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace marsokhod::eval {
namespace {

TEST(Odometry, WithoutSlipTheEstimateIsTheTruth) {
  Odometry odometry({-40.0, 0.0, 0.0}, 0.0, 1);
  const double factor = odometry.next_drive_factor();
  EXPECT_EQ(factor, 1.0);
  odometry.book({-40.0, 0.0, 0.0}, {-37.0, 4.0, 30.0}, factor);
  EXPECT_DOUBLE_EQ(odometry.estimate().x, -37.0);
  EXPECT_DOUBLE_EQ(odometry.estimate().y, 4.0);
  EXPECT_DOUBLE_EQ(odometry.estimate().heading_deg, 30.0);
}

// 8 m on the ground at a factor of 0.8 is 10 m of wheel turns: the estimate says 10 m.
TEST(Odometry, SlipMakesTheEstimateOvershootByOneOverTheFactor) {
  Odometry odometry({0.0, 0.0, 0.0}, 0.2, 1);
  odometry.book({0.0, 0.0, 0.0}, {8.0, 0.0, 0.0}, 0.8);
  EXPECT_DOUBLE_EQ(odometry.estimate().x, 10.0);
  odometry.book({8.0, 0.0, 0.0}, {8.0, 6.0, 90.0}, 0.75); // 6 m north is 8 m believed
  EXPECT_DOUBLE_EQ(odometry.estimate().y, 8.0);
  EXPECT_DOUBLE_EQ(odometry.estimate().heading_deg, 90.0);
}

// s is uniform in [0.5, 1.5) x the mean: for a mean of 0.2 the factor lies in (0.7, 0.9] and
// averages 0.8.
TEST(Odometry, SlipIsDrawnAroundItsMean) {
  Odometry odometry({0.0, 0.0, 0.0}, 0.2, 7);
  double sum = 0.0;
  constexpr int kDraws = 4000;
  for (int k = 0; k < kDraws; ++k) {
    const double factor = odometry.next_drive_factor();
    ASSERT_GT(factor, 0.7);
    ASSERT_LE(factor, 0.9);
    sum += factor;
  }
  EXPECT_NEAR(sum / kDraws, 0.8, 0.005);
}

TEST(Odometry, SlipOutsideItsRangeIsRefused) {
  for (const double slip : {-0.1, 0.6}) {
    try {
      Odometry({0.0, 0.0, 0.0}, slip, 1);
      ADD_FAILURE() << "slip " << slip << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("slip"), std::string::npos);
    }
  }
}

} // namespace
} // namespace marsokhod::eval
