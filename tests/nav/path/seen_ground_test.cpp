// Tests: the ground a pair saw, and the footprint's sweep over ground it did not see, on the
// hand-made long grid, where what is seen and what the footprint covers are hand geometry.

#include "nav/terrain_grid.hpp"

#include "marsokhod/nav/path/seen_ground.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace marsokhod::nav {
namespace {

using testing::grid_terrain;
using testing::long_grid;

constexpr double kUnknown = std::numeric_limits<double>::infinity();
constexpr double kCell = 0.25;

// The long grid (5 cm pixels, 2.0 to 12.35 m ahead, 1.0 m either side) with no point where
// `hidden` says so.
TerrainPoints terrain_without(bool (*hidden)(double forward, double left)) {
  return grid_terrain(
      long_grid(),
      [hidden](double forward, double left) { return hidden(forward, left) ? kUnknown : 0.0; });
}

std::pmr::vector<FootprintConflict> unseen_on(const TerrainPoints& terrain,
                                              const std::vector<DriveCommand>& commands) {
  const ResidentTerrain rows(terrain);
  const SeenGround seen(rows, kCell);
  return footprint_unseen(seen, commands, imaging::Chassis{}, 16);
}

TEST(SeenGround, AGridSeenEverywhereLeavesNothingUnseenOnTheWay) {
  const TerrainPoints terrain = terrain_without([](double, double) { return false; });
  const ResidentTerrain rows(terrain);
  const SeenGround seen(rows, kCell);
  EXPECT_DOUBLE_EQ(seen.nearest_m(), 2.0);
  EXPECT_TRUE(seen.seen(6.0, 0.0));
  // Beyond the grid's 12.35 m and its 1.0 m side, with one cell of neighbours around it.
  EXPECT_FALSE(seen.seen(12.9, 0.0));
  EXPECT_FALSE(seen.seen(6.0, 1.6));
  // A 5 m drive: the footprint (1.85 x 1.20 m) stays within the grid, and the ground behind
  // the first 2.25 m (the nearest point, 2.0 m, and one cell) is known from before.
  EXPECT_TRUE(unseen_on(terrain, {{0.0, 5.0}}).empty());
}

// No point 4.0 to 5.0 m ahead within 0.5 m of the centre line: cells 9 and 10 of the grid
// (4.25 to 4.75 m) and 3 and 4 across (-0.25 to 0.25 m) have no seen neighbour.
TEST(SeenGround, AHoleUnderTheDriveIsUnseenGroundWhereNoNeighbourWasSeen) {
  const TerrainPoints terrain = terrain_without([](double forward, double left) {
    return forward >= 4.0 - 1e-6 && forward < 5.0 - 1e-6 && std::abs(left) < 0.5 - 1e-6;
  });
  const auto unseen = unseen_on(terrain, {{0.0, 5.0}});
  ASSERT_FALSE(unseen.empty());
  EXPECT_GE(unseen[0].hazard.x, 4.25 - 1e-9);
  EXPECT_LT(unseen[0].hazard.x, 4.75);
  EXPECT_LT(std::abs(unseen[0].hazard.y), 0.25);
  EXPECT_TRUE(unseen[0].unseen);
  EXPECT_FALSE(unseen[0].turning);
  // The drive stops 0.8 m short of the hole: its front reaches 3.2 + 0.925 = 4.125 m.
  EXPECT_TRUE(unseen_on(terrain, {{0.0, 3.2}}).empty());
}

TEST(SeenGround, AHoleBesideTheFootprintIsNotOnTheWay) {
  const TerrainPoints terrain = terrain_without(
      [](double forward, double left) { return forward >= 4.0 && forward < 5.0 && left > 0.75; });
  EXPECT_TRUE(unseen_on(terrain, {{0.0, 5.0}}).empty());
}

// Turning left on the spot sweeps only ground within 0.925 m (the nearest 2.25 m is known);
// driving 1.5 m to the left then leaves the view, which ends 1.0 m to the left.
TEST(SeenGround, DrivingOutOfTheViewIsDrivingOnUnseenGround) {
  const TerrainPoints terrain = terrain_without([](double, double) { return false; });
  const auto unseen = unseen_on(terrain, {{90.0, 1.5}});
  ASSERT_FALSE(unseen.empty());
  EXPECT_EQ(unseen[0].command, 0);
  EXPECT_FALSE(unseen[0].turning);
  EXPECT_GT(std::hypot(unseen[0].hazard.x, unseen[0].hazard.y), 2.25);
}

TEST(SeenGround, RefusesACellThatIsNotAPositiveLength) {
  const TerrainPoints terrain = terrain_without([](double, double) { return false; });
  const ResidentTerrain rows(terrain);
  EXPECT_THROW(SeenGround(rows, 0.0), std::invalid_argument);
  EXPECT_THROW(SeenGround(rows, std::nan("")), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
