// The figures of `eval terrain` from hand-made seed outcomes, and the seed-range parser.
#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/eval/terrain/terrain_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::eval {
namespace {

constexpr std::size_t zone(nav::Zone z) {
  return static_cast<std::size_t>(z);
}

// Seed 1: a path, 4 obstacle and 10 free pixels at 2-6 m, 10 free pixels at 6-10 m; eleven
// elevation errors of 1..11 cm at 2-6 m. Seed 2: no path, 6 obstacle and 20 free pixels at
// 6-10 m, 3 of those prohibited as unknown.
std::vector<SeedOutcome> two_seeds() {
  SeedOutcome one;
  one.seed = 1;
  one.bands[0] = {4, 3, 10, 2, {}};
  one.bands[0].free_prohibited_as[zone(nav::Zone::step)] = 1;
  one.bands[0].free_prohibited_as[zone(nav::Zone::margin)] = 1;
  one.bands[1] = {0, 0, 10, 0, {}};
  one.hazards[0] = {4, 2, 10, 1, {}};
  one.found = one.truth_found = true;
  one.seconds = 0.5;
  for (const int cm : {6, 2, 11, 1, 9, 4, 10, 3, 8, 5, 7})
    one.elevation_errors[0].push_back(0.01F * static_cast<float>(cm));
  SeedOutcome two;
  two.seed = 2;
  two.bands[1] = {6, 6, 20, 3, {}};
  two.bands[1].free_prohibited_as[zone(nav::Zone::unknown)] = 3;
  two.truth_found = true;
  two.reason = "no way through";
  two.seconds = 1.5;
  return {one, two};
}

TEST(TerrainFigures, AddUpTheSeedsOverTheNearBandsAndPerBand) {
  const TerrainFigures f = terrain_figures(two_seeds());
  EXPECT_EQ(f.seeds, 2U);
  // 2-10 m: 9 of 10 obstacle pixels prohibited; 5 of 40 free pixels, 3 of them as unknown.
  EXPECT_DOUBLE_EQ(f.obstacle_recall, 90.0);
  EXPECT_DOUBLE_EQ(f.false_prohibited, 12.5);
  EXPECT_DOUBLE_EQ(f.false_prohibited_by_zone[zone(nav::Zone::unknown)], 7.5);
  EXPECT_DOUBLE_EQ(f.false_prohibited_by_zone[zone(nav::Zone::step)], 2.5);
  EXPECT_DOUBLE_EQ(f.false_prohibited_by_zone[zone(nav::Zone::slope)], 0.0);
  EXPECT_DOUBLE_EQ(f.false_prohibited_by_zone[zone(nav::Zone::margin)], 2.5);
  EXPECT_EQ(f.paths_found, 1);
  EXPECT_EQ(f.ground_truth_paths, 2);
  EXPECT_EQ(f.paths_found_where_ground_truth_has_one, 1);
  EXPECT_EQ(f.unsafe_paths, 0);
  EXPECT_DOUBLE_EQ(f.navigation_seconds_per_seed, 1.0);
  EXPECT_DOUBLE_EQ(f.navigation_ms_per_seed, 1000.0);

  const BandFigures& near = f.bands[0];
  EXPECT_EQ(near.band_m, "2-6");
  EXPECT_EQ(near.obstacle_pixels, 4U);
  EXPECT_DOUBLE_EQ(near.obstacle_recall, 75.0);
  EXPECT_EQ(near.free_pixels, 10U);
  EXPECT_DOUBLE_EQ(near.false_prohibited, 20.0);
  EXPECT_DOUBLE_EQ(near.hazard_recall, 50.0);
  EXPECT_DOUBLE_EQ(near.false_hazard, 10.0);
  // Quantiles of 1..11 cm: the 6th (median) and the 10th value (90 % and 99 %).
  EXPECT_NEAR(near.elevation_error_cm[0], 6.0, 1e-4);
  EXPECT_NEAR(near.elevation_error_cm[1], 10.0, 1e-4);
  EXPECT_NEAR(near.elevation_error_cm[2], 10.0, 1e-4);

  EXPECT_EQ(f.bands[1].band_m, "6-10");
  EXPECT_EQ(f.bands[1].obstacle_pixels, 6U);
  EXPECT_EQ(f.bands[1].free_pixels, 30U);
  EXPECT_DOUBLE_EQ(f.bands[1].false_prohibited, 10.0);
  EXPECT_TRUE(std::isnan(f.bands[1].elevation_error_cm[0]));
  EXPECT_EQ(f.bands[2].band_m, "10-14");
  EXPECT_TRUE(std::isnan(f.bands[2].obstacle_recall));
  EXPECT_TRUE(std::isnan(f.bands[2].hazard_recall));
}

TEST(TerrainFigures, NoSeedsGiveNoNumbersAndNoTime) {
  const TerrainFigures f = terrain_figures({});
  EXPECT_EQ(f.seeds, 0U);
  EXPECT_TRUE(std::isnan(f.obstacle_recall));
  EXPECT_TRUE(std::isnan(f.false_prohibited));
  EXPECT_DOUBLE_EQ(f.navigation_seconds_per_seed, 0.0);
  EXPECT_DOUBLE_EQ(f.navigation_ms_per_seed, 0.0);
}

TEST(Quantile, PicksTheLowerOfTwoNeighboursAndIsNotANumberWhenEmpty) {
  std::vector<float> values = {4.0F, 1.0F, 3.0F, 2.0F};
  EXPECT_DOUBLE_EQ(quantile(values, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(quantile(values, 1.0), 4.0);
  std::vector<float> none;
  EXPECT_TRUE(std::isnan(quantile(none, 0.5)));
}

TEST(SeedRange, ReadsARangeAndASingleSeed) {
  const SeedRange range = parse_seed_range("3..50");
  EXPECT_EQ(range.first, 3U);
  EXPECT_EQ(range.last, 50U);
  const SeedRange one = parse_seed_range("7");
  EXPECT_EQ(one.first, 7U);
  EXPECT_EQ(one.last, 7U);
}

TEST(SeedRange, MalformedBackwardsAndLongRangesAreOptionErrorsQuotingTheText) {
  const auto message = [](const std::string& text) {
    try {
      parse_seed_range(text);
    } catch (const OptionError& error) {
      return std::string(error.what());
    }
    ADD_FAILURE() << "no OptionError for " << text;
    return std::string();
  };
  const std::string expected = ": expected A..B (e.g. 1..50) or a single seed, each a whole "
                               "number from 0 to 18446744073709551615";
  EXPECT_EQ(message("abc"), "'abc'" + expected);
  EXPECT_EQ(message("1.."), "'1..'" + expected);
  EXPECT_EQ(message("-1..2"), "'-1..2'" + expected);
  EXPECT_EQ(message("5..3"), "'5..3': the last seed is below the first");
  EXPECT_EQ(message("1..10001"), "'1..10001': at most 10000 seeds at a time");
  EXPECT_NO_THROW(parse_seed_range("1..10000"));
}

// Seeds are read as checked unsigned 64-bit integers: no wrap, no junk, the whole range legal.
TEST(SeedRange, SeedsAreWholeUnsigned64BitNumbersWithoutWrapOrJunk) {
  // 2^64 - 1 is the largest seed `world --seed` takes; 2^64 would wrap to 0.
  const SeedRange top = parse_seed_range("18446744073709551614..18446744073709551615");
  EXPECT_EQ(top.first, 18446744073709551614U);
  EXPECT_EQ(top.last, 18446744073709551615U);
  // Leading zeros are decimal, not octal.
  EXPECT_EQ(parse_seed_range("010").first, 10U);
  std::vector<std::string> taken;
  for (const char* text : {"18446744073709551616", "1..18446744073709551616", "", "..", "1x",
                           "1..2x", "+1", "1e3", "0x10", "1...3", "1..2..3", " 1", "1 ..2"}) {
    try {
      parse_seed_range(text);
      taken.push_back(text);
    } catch (const OptionError&) {
    }
  }
  EXPECT_EQ(taken, std::vector<std::string>{});
}

// A range ending at the largest seed is counted, so the loop over it ends.
TEST(SeedRange, ARangeEndingAtTheLargestSeedVisitsEachSeedOnce) {
  std::vector<std::uint64_t> seen;
  TerrainEvaluationOptions options;
  options.size = 32;
  options.terrain_size = 16.0;
  evaluate_seeds(parse_seed_range("18446744073709551615"), options,
                 [&](std::uint64_t position, std::uint64_t count, std::uint64_t seed) {
                   EXPECT_EQ(position, 1U);
                   EXPECT_EQ(count, 1U);
                   seen.push_back(seed);
                 });
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen.front(), 18446744073709551615U);
}

} // namespace
} // namespace marsokhod::eval
