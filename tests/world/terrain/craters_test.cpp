// Tests: crater sizes follow the power law, and crater relief has floor, rim and ejecta.

#include "marsokhod/world/terrain/craters.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace marsokhod::world {
namespace {

TEST(Craters, CraterDiametersFollowThePowerLawAndSomeArePits) {
  const std::vector<Crater> craters = sample_craters({1.0, Eigen::Vector2d(100.0, 100.0), 0.0}, 17);
  ASSERT_GT(craters.size(), 9000u);
  int bowls = 0;
  int bowls_above_1m = 0;
  int pits = 0;
  for (const Crater& crater : craters) {
    if (crater.pit) {
      ++pits;
      EXPECT_GE(crater.depth_m, 0.35 * crater.diameter_m);
      continue;
    }
    ++bowls;
    bowls_above_1m += crater.diameter_m >= 1.0;
    EXPECT_NEAR(crater.depth_m / crater.diameter_m, 0.19, 0.031);
  }
  // N(>= D) ~ D^-2 truncated to 0.5 .. 6 m: share above 1 m = (1 - 1/36) / (4 - 1/36).
  const double expected = (1.0 - 1.0 / 36.0) / (4.0 - 1.0 / 36.0);
  EXPECT_NEAR(static_cast<double>(bowls_above_1m) / bowls, expected, 0.02);
  EXPECT_NEAR(static_cast<double>(pits) / static_cast<double>(craters.size()), 0.15, 0.02);
}

TEST(Craters, CraterReliefHasFloorRimAndEjecta) {
  HeightField flat(301, 301, 0.02, Eigen::Vector2d(-3.0, -3.0));
  Crater crater;
  crater.diameter_m = 2.0;
  crater.depth_m = 0.4;       // floor 0.4 m below the rim crest
  crater.rim_height_m = 0.08; // crest 8 cm above the plain
  carve_craters({crater}, flat);
  EXPECT_NEAR(flat.height(0.0, 0.0), 0.08 - 0.4, 1e-6);
  EXPECT_NEAR(flat.height(1.0, 0.0), 0.08, 1e-6);
  EXPECT_NEAR(flat.height(0.0, -1.0), 0.08, 1e-6);
  EXPECT_GT(flat.height(1.5, 0.0), 0.0); // ejecta
  EXPECT_LT(flat.height(1.5, 0.0), 0.08);
  EXPECT_EQ(flat.height(2.5, 0.0), 0.0); // beyond two radii the plain is untouched
}

} // namespace
} // namespace marsokhod::world
