// Tests: the cycle's path checked by the footprint, planned again around what it met, on
// hand-made terrain.

#include "nav/terrain_grid.hpp"

#include "marsokhod/nav/cycle/checked_path.hpp"
#include "marsokhod/nav/path/footprint_check.hpp"
#include "marsokhod/nav/path/seen_ground.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace marsokhod::nav {
namespace {

using testing::grid_forward;
using testing::grid_left;
using testing::grid_terrain;
using testing::GridSpec;
using testing::long_grid;

// Flat ground seen as the long grid (column 20 straight ahead, 5 cm a pixel, rows 2.0 to
// 12.35 m ahead), everything traversable but `steps`.
struct CheckScene {
  GridSpec grid = long_grid();
  TerrainPoints terrain = grid_terrain(grid, [](double, double) { return 0.0; });
  ZoneMap zones{imaging::Image<std::uint8_t>(grid.width, grid.height, 1, 0), {}};

  void step_at(int x, int y) { zones.zone(x, y) = static_cast<std::uint8_t>(Zone::step); }
  double distance(PixelPoint p, double forward, double left) const {
    return std::hypot(grid_forward(grid, p.y) - forward, grid_left(grid, p.x) - left);
  }
};

// Unchecked, the path runs straight to 10.0 m, and the front of the rover (0.925 m ahead of
// its centre, 1.025 m with the check's 0.10 m allowance ahead) would stand on a step 10.80 m
// ahead.
// Checked, the target keeps the half-diagonal of the checked footprint (1.025 by 0.60 m) from it.
TEST(PlanCyclePath, PlansAroundAStepTheFootprintWouldMeetAtTheEnd) {
  CheckScene scene;
  scene.step_at(20, 207 - 176); // 10.80 m ahead, straight
  const ZoneMap before{scene.zones.zone, scene.zones.counts};
  const PathPlan unchecked = plan_path(scene.terrain, scene.zones, PlannerOptions{});
  ASSERT_TRUE(unchecked.found);
  EXPECT_LT(scene.distance(unchecked.target, 10.80, 0.0), 1.0);

  const PathPlan plan =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, {});
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_GE(scene.distance(plan.target, 10.80, 0.0), std::hypot(1.025, 0.60));
  EXPECT_EQ(scene.zones.zone, before.zone) << "the zones are given back as they were";
  const DrivePlan drive = plan_drive(scene.terrain, plan.pixels, DriveOptions{});
  imaging::Chassis checked;
  checked.wheel_diameter_m += 0.2;
  EXPECT_TRUE(
      footprint_conflicts(ResidentTerrain(scene.terrain), scene.zones, drive.commands, checked, 4)
          .empty());
}

// A row of steps 10.50 m ahead across the whole view: every point of the target band before it
// lies within a footprint's length of it, and none beyond can be reached.
TEST(PlanCyclePath, SaysNoPathWhenEveryPathPutsTheFootprintOnAStep) {
  CheckScene scene;
  for (int x = 0; x < scene.grid.width; ++x)
    scene.step_at(x, 207 - 170);
  const ZoneMap before{scene.zones.zone, scene.zones.counts};
  ASSERT_TRUE(plan_path(scene.terrain, scene.zones, PlannerOptions{}).found);
  const PathPlan plan =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, {});
  EXPECT_FALSE(plan.found);
  EXPECT_NE(plan.reason.find("footprint meets a step or slope 10.50 m ahead"), std::string::npos)
      << plan.reason;
  EXPECT_EQ(scene.zones.zone, before.zone);
}

// The view begins 2.0 m ahead; a wall of remembered steps 1.50 m ahead, across the whole
// width the rover could turn into, lies on the drive to any start. Remembered steps far to the
// side leave the plan as it was.
TEST(PlanCyclePath, RefusesEveryPathWhoseDriveCrossesARememberedStep) {
  CheckScene scene;
  std::vector<GroundPoint> wall;
  for (int k = -80; k <= 80; ++k)
    wall.push_back({1.50, 0.05 * k});
  FootprintCheckOptions remembering;
  remembering.remembered = wall;
  const PathPlan blocked =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, remembering);
  EXPECT_FALSE(blocked.found);
  EXPECT_NE(blocked.reason.find("1.50 m ahead"), std::string::npos) << blocked.reason;

  const std::vector<GroundPoint> aside{{1.50, 6.0}, {1.50, -6.0}};
  remembering.remembered = aside;
  const PathPlan plan =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, remembering);
  const PathPlan unchecked = plan_path(scene.terrain, scene.zones, PlannerOptions{});
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_EQ(plan.pixels, unchecked.pixels);
}

// Flat ground whose pixels more than 0.05 m left of the centre line, from 6.0 to 7.0 m ahead,
// are seen 1.0 m farther, as if nearer ground hid that patch from the cameras: every pixel is
// known and traversable, and no point lies in the patch, which only the seen-ground check can
// tell.
TerrainPoints terrain_with_hidden_patch(const GridSpec& grid) {
  TerrainPoints terrain = grid_terrain(grid, [](double, double) { return 0.0; });
  for (int y = 0; y < grid.height; ++y) {
    const double forward = grid_forward(grid, y);
    if (forward < 6.0 - 1e-6 || forward >= 7.0 - 1e-6)
      continue;
    for (int x = 0; x < grid.width; ++x)
      if (grid_left(grid, x) > 0.05 + 1e-6)
        terrain.forward(x, y) = static_cast<float>(forward + 1.0);
  }
  return terrain;
}

std::pmr::vector<FootprintConflict> unseen_under(const TerrainPoints& terrain,
                                                 const PathPlan& plan) {
  const DrivePlan drive = plan_drive(terrain, plan.pixels, DriveOptions{});
  const SeenGround seen(ResidentTerrain(terrain), 0.25);
  return footprint_unseen(seen, drive.commands, imaging::Chassis{}, 4);
}

// Unchecked, the path runs straight ahead and the footprint's left half (0 to 0.60 m) crosses
// the patch, whose cells 6.25 to 6.75 m ahead and 0.30 m and more to the left have no seen
// neighbour. Checked, on ground 2.0 m either side, the path keeps the footprint off it.
TEST(PlanCyclePath, KeepsTheFootprintOffGroundThePairDidNotSee) {
  CheckScene scene;
  scene.grid = GridSpec{81, 208, 0.05, 2.0};
  scene.terrain = terrain_with_hidden_patch(scene.grid);
  scene.zones = ZoneMap{imaging::Image<std::uint8_t>(81, 208, 1, 0), {}};
  const PathPlan unchecked = plan_path(scene.terrain, scene.zones, PlannerOptions{});
  ASSERT_TRUE(unchecked.found) << unchecked.reason;
  EXPECT_FALSE(unseen_under(scene.terrain, unchecked).empty());
  FootprintCheckOptions seeing;
  seeing.unseen_cell_m = 0.25;
  const PathPlan plan =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, seeing);
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_TRUE(unseen_under(scene.terrain, plan).empty());
  EXPECT_NE(plan.pixels, unchecked.pixels);
}

// On the long grid, 1.0 m either side, the footprint (1.20 m wide) cannot pass the patch
// without leaving the view on the right: no path, saying why.
TEST(PlanCyclePath, SaysNoPathWhenEveryPathCrossesGroundThePairDidNotSee) {
  CheckScene scene;
  scene.terrain = terrain_with_hidden_patch(scene.grid);
  FootprintCheckOptions seeing;
  seeing.unseen_cell_m = 0.25;
  const PathPlan plan =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, seeing);
  EXPECT_FALSE(plan.found);
  EXPECT_NE(plan.reason.find("footprint meets ground the pair did not see"), std::string::npos)
      << plan.reason;
}

TEST(PlanCyclePath, WithoutTheCheckIsThePlannersPath) {
  CheckScene scene;
  scene.step_at(20, 207 - 176);
  FootprintCheckOptions off;
  off.paths = 0;
  const PathPlan plan =
      plan_cycle_path(scene.terrain, scene.zones, PlannerOptions{}, DriveOptions{}, off);
  const PathPlan planner = plan_path(scene.terrain, scene.zones, PlannerOptions{});
  EXPECT_EQ(plan.pixels, planner.pixels);
}

TEST(PlanCyclePath, RefusesBadCheckOptions) {
  CheckScene scene;
  FootprintCheckOptions negative;
  negative.paths = -1;
  EXPECT_THROW(plan_cycle_path(scene.terrain, scene.zones, {}, {}, negative),
               std::invalid_argument);
  FootprintCheckOptions allowance;
  allowance.allowance_m = -0.1;
  EXPECT_THROW(plan_cycle_path(scene.terrain, scene.zones, {}, {}, allowance),
               std::invalid_argument);
  FootprintCheckOptions cell;
  cell.unseen_cell_m = -0.25;
  EXPECT_THROW(plan_cycle_path(scene.terrain, scene.zones, {}, {}, cell), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
