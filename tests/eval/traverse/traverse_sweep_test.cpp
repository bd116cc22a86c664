// Tests: the figures of a traverse sweep from hand-written trial lines, where every figure is
// arithmetic on the lines.

#include "marsokhod/eval/traverse/traverse_sweep.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::eval {
namespace {

std::string trial(int k, const char* outcome, double distance, double efficiency, int stops,
                  int hand_overs, double mission, double driving, const char* fault = "") {
  return fmt::format(R"({{"trial":{},"outcome":"{}","distance_m":{},"path_efficiency":{},)"
                     R"("emergency_stops":{},"hand_overs":{},"mission_seconds":{},)"
                     R"("driving_seconds":{},"fault_outcome":"{}"}})",
                     k, outcome, distance, efficiency, stops, hand_overs, mission, driving, fault);
}

TEST(TraverseSweep, FiguresPerRockCoverAreTheTrialsArithmetic) {
  TraverseSweep sweep;
  sweep.first_seed = 1;
  sweep.last_seed = 3;
  sweep.rocks = {0.0, 0.1};
  const std::vector<std::string> lines = {
      trial(0, "success", 80.0, 0.9, 1, 0, 900.0, 800.0),
      trial(1, "success", 100.0, 0.8, 0, 0, 1100.0, 1000.0, "recovered"),
      trial(2, "unsafe", 20.0, 0.0, 1, 0, 200.0, 200.0, "safe_stop"),
      trial(3, "hand_over", 50.0, 0.0, 2, 1, 600.0, 500.0, "recovered"),
      trial(4, "timeout", 50.0, 0.0, 0, 0, 600.0, 500.0),
      trial(5, "hand_over", 0.0, 0.0, 0, 1, 0.0, 0.0),
  };
  const std::vector<RockFigures> f = sweep_figures(sweep, lines);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].trials, 3u);
  EXPECT_EQ(f[0].outcomes.at("success"), 2u);
  EXPECT_EQ(f[0].outcomes.at("unsafe"), 1u);
  EXPECT_EQ(f[0].outcomes.at("timeout"), 0u);
  EXPECT_DOUBLE_EQ(f[0].success_rate, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(f[0].spl, (0.9 + 0.8) / 3.0);
  EXPECT_EQ(f[0].unsafe_trials, 1u);
  EXPECT_DOUBLE_EQ(f[0].emergency_stops_per_100m, 2.0 * 100.0 / 200.0);
  EXPECT_DOUBLE_EQ(f[0].metres_per_hour, 200.0 * 3600.0 / 2200.0);
  EXPECT_DOUBLE_EQ(f[0].metres_per_hour_driving, 200.0 * 3600.0 / 2000.0);
  const Interval expected = wilson_95(2, 3);
  EXPECT_DOUBLE_EQ(f[0].success_ci95.low, expected.low);
  EXPECT_DOUBLE_EQ(f[0].success_ci95.high, expected.high);

  EXPECT_EQ(f[1].rocks, 0.1);
  EXPECT_EQ(f[1].outcomes.at("hand_over"), 2u);
  EXPECT_DOUBLE_EQ(f[1].success_rate, 0.0);
  EXPECT_DOUBLE_EQ(f[1].hand_overs_per_100m, 2.0 * 100.0 / 100.0);

  // Only the trials a fault struck are counted, by the fault run's outcome.
  EXPECT_EQ(f[0].fault_outcomes,
            (std::map<std::string, std::uint64_t>{{"recovered", 1}, {"safe_stop", 1}}));
  EXPECT_EQ(f[1].fault_outcomes, (std::map<std::string, std::uint64_t>{{"recovered", 1}}));
}

TEST(TraverseSweep, BadSweepsAreRefused) {
  TraverseSweep sweep;
  sweep.rocks = {};
  EXPECT_THROW(validate(sweep), std::invalid_argument);
  sweep.rocks = {0.6};
  EXPECT_THROW(validate(sweep), std::invalid_argument);
  sweep.rocks = {0.1};
  sweep.jobs = 0;
  EXPECT_THROW(validate(sweep), std::invalid_argument);
  sweep.jobs = 1;
  sweep.first_seed = 5;
  sweep.last_seed = 4;
  EXPECT_THROW(validate(sweep), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::eval
