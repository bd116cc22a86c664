// The scan-line dynamic programme, the left-right check and the fill policy on hand-made lines.
#include "nav/stereo_test_support.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav/matching/scanline_dp.hpp"
#include "marsokhod/nav/stereo/consistency_check.hpp"
#include "marsokhod/nav/stereo/disparity_fill.hpp"
#include "marsokhod/nav/stereo/disparity_metrics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace marsokhod::nav {
namespace {

using test_support::kInf;

// The step profile 3 (x < 20), 9 (20..39), 5 (x >= 40) over 60 pixels and 12 candidates.
int step_profile(int x) {
  return x < 20 ? 3 : (x < 40 ? 9 : 5);
}

// Costs that favour the profile (10 per pixel of distance, capped) but lie at every seventh
// pixel: there a wrong disparity costs 0 and the true one 12, so choosing pixel by pixel fails.
std::vector<std::uint16_t> step_costs(int width, int candidates) {
  std::vector<std::uint16_t> costs(static_cast<std::size_t>(width * candidates));
  for (int x = 0; x < width; ++x)
    for (int d = 0; d < candidates; ++d) {
      int cost = std::min(10 * std::abs(d - step_profile(x)), 60);
      if (x % 7 == 3)
        cost = d == (step_profile(x) + 4) % candidates ? 0 : (d == step_profile(x) ? 12 : cost);
      costs[static_cast<std::size_t>(x * candidates + d)] = static_cast<std::uint16_t>(cost);
    }
  return costs;
}

TEST(ScanlineDp, RecoversAStepProfileExactlyWhereWinnerTakesAllFails) {
  constexpr int kWidth = 60;
  constexpr int kCandidates = 12;
  const std::vector<std::uint16_t> costs = step_costs(kWidth, kCandidates);
  // Pixel by pixel the decoys win.
  int decoys_won = 0;
  for (int x = 0; x < kWidth; ++x) {
    const auto* row = costs.data() + x * kCandidates;
    decoys_won += std::min_element(row, row + kCandidates) - row != step_profile(x) ? 1 : 0;
  }
  ASSERT_GE(decoys_won, 8);
  const std::vector<int> chosen = scanline_disparities(costs, kWidth, kCandidates, DpPenalties{});
  for (int x = 0; x < kWidth; ++x)
    EXPECT_EQ(chosen[static_cast<std::size_t>(x)], step_profile(x)) << "x = " << x;
}

TEST(ScanlineDp, WithoutPenaltiesEachPixelTakesItsCheapestDisparity) {
  constexpr int kWidth = 60;
  constexpr int kCandidates = 12;
  const std::vector<std::uint16_t> costs = step_costs(kWidth, kCandidates);
  const std::vector<int> chosen =
      scanline_disparities(costs, kWidth, kCandidates, DpPenalties{0, 0, 0, 10});
  for (int x = 0; x < kWidth; ++x) {
    const auto* row = costs.data() + x * kCandidates;
    EXPECT_EQ(chosen[static_cast<std::size_t>(x)], std::min_element(row, row + kCandidates) - row);
  }
}

TEST(ScanlineDp, RejectsCostTablesOfTheWrongSizeOrRange) {
  const std::vector<std::uint16_t> costs(10, 1);
  EXPECT_THROW(scanline_disparities(costs, 3, 4, DpPenalties{}), std::invalid_argument);
  std::vector<std::uint16_t> too_high(12, 1);
  too_high[5] = 300;
  EXPECT_THROW(scanline_disparities(too_high, 3, 4, DpPenalties{}), std::invalid_argument);
  EXPECT_THROW(
      scanline_disparities(std::vector<std::uint16_t>(12, 1), 3, 4, DpPenalties{-1, 5, 5, 5}),
      std::invalid_argument);
}

// Aggregated costs S of a line: S(x, d) = 10 except where `cheap` lists (x, d, s).
struct Cheap {
  int x, d, s;
};
std::vector<std::uint16_t> aggregated_line(int width, int candidates,
                                           std::initializer_list<Cheap> cheap) {
  std::vector<std::uint16_t> s(static_cast<std::size_t>(width * candidates), 10);
  for (const Cheap& c : cheap)
    s[static_cast<std::size_t>(c.x * candidates + c.d)] = static_cast<std::uint16_t>(c.s);
  return s;
}

TEST(ConsistencyCheck, TheRightViewTakesTheCheapestAggregatedCostAlongItsOwnLine) {
  // Right pixel 2 is met by (x 2, d 0), (3, 1), (4, 2) and (5, 3); (4, 2) is the cheapest.
  // Right pixel 5 is met only by (5, 0), (6, 1) and (7, 2), all equal: the smallest d wins.
  const std::vector<std::uint16_t> s = aggregated_line(8, 4, {{4, 2, 3}, {5, 3, 4}});
  const std::vector<int> right = right_view_disparities(s, 8, 4);
  EXPECT_EQ(right[2], 2);
  EXPECT_EQ(right[5], 0);
  // Left pixel 5 chose d 3 (right pixel 2, which prefers d 2): within 1, so it agrees; a left
  // pixel 7 that chose d 2 lands on right pixel 5, which chose d 0, and fails.
  std::vector<std::uint8_t> valid(8);
  const std::vector<int> left = {0, 0, 0, 0, 2, 3, 0, 2};
  check_left_right(left, right, 1, valid);
  EXPECT_EQ(valid[5], 255);
  EXPECT_EQ(valid[7], 0);
}

TEST(ConsistencyCheck, AMismatchNobodyElseClaimsStillFailsAgainstTheRightView) {
  // Left pixel 6 picks d 4 (right pixel 2) on a cheap S, but right pixel 2's own line finds a
  // cheaper match at d 1 (left pixel 3): the claim alone would stand, the right view does not.
  const std::vector<std::uint16_t> s = aggregated_line(8, 5, {{6, 4, 5}, {3, 1, 2}});
  const std::vector<int> right = right_view_disparities(s, 8, 5);
  EXPECT_EQ(right[2], 1);
  std::vector<std::uint8_t> valid(8);
  check_left_right(std::vector<int>{0, 0, 0, 1, 0, 0, 4, 0}, right, 1, valid);
  EXPECT_EQ(valid[6], 0);
  EXPECT_EQ(valid[3], 255);
}

TEST(ConsistencyCheck, PixelsWhoseSceneTheRightImageCannotShowTakeNoPartInTheRightView) {
  // Left pixel 3 outbids left pixel 8 for right pixel 1 (S 1 at d 2 against S 4 at d 7): left
  // pixel 8 fails. With the first 5 columns unseen, pixel 3 no longer competes, right pixel 1
  // takes d 7 and pixel 8 passes; right pixel 0, met only by unseen pixels 0..4 and by the
  // seen pixels 5..7 at d 5..7, now takes d 5 (all S 10, the smallest d).
  const std::vector<std::uint16_t> s = aggregated_line(10, 8, {{3, 2, 1}, {8, 7, 4}});
  std::vector<std::uint8_t> valid(10);
  const std::vector<int> left = {0, 0, 0, 2, 0, 0, 0, 0, 7, 0};
  const std::vector<int> all = right_view_disparities(s, 10, 8);
  EXPECT_EQ(all[1], 2);
  EXPECT_EQ(all[0], 0);
  check_left_right(left, all, 1, valid);
  EXPECT_EQ(valid[8], 0);
  const std::vector<int> seen = right_view_disparities(s, 10, 8, 5);
  EXPECT_EQ(seen[1], 7);
  EXPECT_EQ(seen[0], 5);
  check_left_right(left, seen, 1, valid);
  EXPECT_EQ(valid[8], 255);
  // Unseen pixels still get a right view's verdict: pixel 3's right pixel 1 now disagrees.
  EXPECT_EQ(valid[3], 0);
  // With every column unseen no right pixel is met.
  const std::vector<int> none = right_view_disparities(s, 10, 8, 10);
  EXPECT_TRUE(std::all_of(none.begin(), none.end(), [](int d) { return d == -1; }));
}

TEST(ConsistencyCheck, TheRightViewAgreesWithABruteForceMinimumOnRandomLines) {
  std::uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525U + 1013904223U;
    return state >> 8;
  };
  for (int trial = 0; trial < 200; ++trial) {
    const int width = 1 + static_cast<int>(next() % 40);
    const int candidates = 1 + static_cast<int>(next() % 12);
    std::vector<std::uint16_t> s(static_cast<std::size_t>(width * candidates));
    for (std::uint16_t& v : s)
      v = static_cast<std::uint16_t>(next() % 16); // many ties
    const std::vector<int> right = right_view_disparities(s, width, candidates);
    for (int r = 0; r < width; ++r) {
      int expected = -1;
      int best = 0;
      for (int d = 0; d < candidates && r + d < width; ++d) {
        const int v = s[static_cast<std::size_t>((r + d) * candidates + d)];
        if (expected < 0 || v < best) {
          expected = d;
          best = v;
        }
      }
      ASSERT_EQ(right[static_cast<std::size_t>(r)], expected)
          << "trial " << trial << " r " << r << " width " << width << " candidates " << candidates;
    }
  }
}

TEST(ConsistencyCheck, TheRightViewRejectsAVolumeOfTheWrongSize) {
  EXPECT_THROW(right_view_disparities(std::vector<std::uint16_t>(11), 3, 4), std::invalid_argument);
  EXPECT_THROW(right_view_disparities({}, 0, 4), std::invalid_argument);
}

TEST(ConsistencyCheck, ToleranceAcceptsNeighbouringDisparitiesAndTheImageEdgeIsUnreliable) {
  const std::vector<int> left = {2, 1, 1};
  const std::vector<int> right = {2, 1, -1};
  std::vector<std::uint8_t> valid(3);
  // x=0: 0-2 < 0 -> outside; x=1: right[0] = 2 vs 1 -> within 1; x=2: right[1] = 1 -> agrees.
  EXPECT_EQ(check_left_right(left, right, 1, valid), 2);
  EXPECT_EQ(valid, (std::vector<std::uint8_t>{0, 255, 255}));
  EXPECT_EQ(check_left_right(left, right, 0, valid), 1);
}

TEST(DisparityFill, RunsTakeTheSmallerOfTheirBoundingValuesAndEdgesTheirOneNeighbour) {
  imaging::Image<float> disparity(8, 1);
  const float values[8] = {kInf, 7, kInf, kInf, 3, kInf, 5, kInf};
  std::copy(values, values + 8, disparity.data());
  imaging::Image<std::uint8_t> valid(8, 1);
  const std::uint8_t reliable[8] = {0, 255, 0, 0, 255, 0, 255, 0};
  std::copy(reliable, reliable + 8, valid.data());
  EXPECT_EQ(fill_disparity(disparity.view(), valid.view(), FillPolicy::background_along_row), 5U);
  const std::vector<float> filled(disparity.data(), disparity.data() + 8);
  EXPECT_EQ(filled, (std::vector<float>{7, 7, 3, 3, 3, 3, 5, 5}));
}

TEST(DisparityFill, ARowWithoutReliablePixelsCopiesTheNearestRowAndNoneLeavesUnknowns) {
  imaging::Image<float> disparity(3, 3, 1, kInf);
  imaging::Image<std::uint8_t> valid(3, 3);
  disparity(0, 2) = 4;
  valid(0, 2) = 255;
  imaging::Image<float> untouched = disparity;
  EXPECT_EQ(fill_disparity(untouched.view(), valid.view(), FillPolicy::none), 0U);
  EXPECT_TRUE(std::isinf(untouched(1, 1)));
  fill_disparity(disparity.view(), valid.view(), FillPolicy::background_along_row);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      EXPECT_EQ(disparity(x, y), 4.0F);
}

TEST(DisparityFill, MedianMatchesSortingEachNineNeighbourWindow) {
  const imaging::Image<std::uint8_t> dots = testing::random_dots(23, 11, 5);
  imaging::Image<float> field(23, 11);
  for (std::size_t i = 0; i < dots.size(); ++i)
    field.data()[i] = static_cast<float>(dots.data()[i]) * 0.25F;
  imaging::Image<float> median(23, 11);
  median3x3(field.view(), median.view());
  for (int y = 0; y < 11; ++y)
    for (int x = 0; x < 23; ++x) {
      std::array<float, 9> window{};
      int i = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          window[static_cast<std::size_t>(i++)] =
              field(std::clamp(x + dx, 0, 22), std::clamp(y + dy, 0, 10));
      std::sort(window.begin(), window.end());
      ASSERT_EQ(median(x, y), window[4]) << x << "," << y;
    }
}

TEST(DisparityFill, PoliciesReadBackFromTheirNames) {
  EXPECT_EQ(parse_fill_policy("background"), FillPolicy::background_along_row);
  EXPECT_EQ(parse_fill_policy("none"), FillPolicy::none);
  EXPECT_FALSE(parse_fill_policy("nearest").has_value());
}

} // namespace
} // namespace marsokhod::nav

namespace marsokhod::nav {
namespace {

TEST(DisparityMetrics, MissingEstimatesCountAsBadAndUnknownTruthIsSkipped) {
  imaging::Image<float> truth(4, 1);
  imaging::Image<float> estimate(4, 1);
  const float known[4] = {0.0F, 5.0F, 5.0F, 5.0F}; // 0 = unknown
  const float guessed[4] = {9.0F, 5.9F, 3.0F, kInf};
  std::copy(known, known + 4, truth.data());
  std::copy(guessed, guessed + 4, estimate.data());
  const BadPixelScore score = score_bad_pixels(estimate.view(), truth.view(), {}, 1.0F);
  EXPECT_EQ(score.scored, 3U);
  EXPECT_EQ(score.bad, 2U); // 3.0 is 2 px off, +inf is missing
  imaging::Image<std::uint8_t> mask(4, 1);
  mask(1, 0) = 255;
  EXPECT_EQ(score_bad_pixels(estimate.view(), truth.view(), mask.view(), 1.0F).bad, 0U);
}

} // namespace
} // namespace marsokhod::nav
