// Terrain read row by row: rows worked out again from the disparity are reconstruct_terrain's,
// bit for bit, each one reported every time it is worked out; the zones and the path on them
// are those on the whole maps.

#include "nav/paper_rig.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/terrain/terrain_rows.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

using test_support::kInf;

using test_rigs::rig_of_side;

/// Counts what RecomputedTerrain reports.
class Tally final : public DynamicMeter {
public:
  void operator()(Work kind, std::uint64_t count) override { counts(kind, count); }
  CountingMeter counts;
};

// Level ground with a wall standing across columns 112..127, to the right: the rows whose
// ground lies between the wall's foot (row 75) and row 40 see its face at the foot's disparity
// instead; the sky is unknown and three disparities are unusable. Enough for a step, its
// margin and a path beside it.
imaging::Image<float> wall_scene(const imaging::StereoRig& rig) {
  imaging::Image<float> disparity(rig.width(), rig.height(), 1, kInf);
  const double foot = rig.ground_disparity(60, 75);
  const double top = rig.ground_disparity(60, 40);
  for (int v = 0; v < rig.height(); ++v)
    for (int u = 0; u < rig.width(); ++u) {
      const double ground = rig.ground_disparity(u, v);
      if (ground <= 0.0)
        continue;
      const bool wall = u >= 112 && ground < foot && ground > top;
      disparity(u, v) = static_cast<float>(wall ? foot : ground);
    }
  disparity(5, 100) = std::numeric_limits<float>::quiet_NaN();
  disparity(6, 100) = 0.0F;
  disparity(7, 100) = -2.0F;
  return disparity;
}

bool same_row(const float* a, const float* b, int width) {
  return std::memcmp(a, b, static_cast<std::size_t>(width) * sizeof(float)) == 0;
}

TEST(RecomputedTerrain, RowsWorkedOutAgainAreTheReconstructedRowsBitForBit) {
  const imaging::StereoRig rig = rig_of_side(128);
  const imaging::Image<float> disparity = wall_scene(rig);
  const imaging::Attitude attitude{3.0, -2.0};
  const TerrainPoints whole = reconstruct_terrain(disparity, rig, attitude);
  Tally tally;
  const RecomputedTerrain rows(disparity, rig, attitude, whole.known_pixels, tally);
  EXPECT_EQ(rows.width(), 128);
  EXPECT_EQ(rows.height(), 128);
  EXPECT_EQ(rows.known_pixels(), whole.known_pixels);
  for (int y = 127; y >= 0; y -= 3) {
    const TerrainRows::Row row = rows.row(y);
    EXPECT_TRUE(same_row(row.forward, whole.forward.row(y), 128)) << y;
    EXPECT_TRUE(same_row(row.left, whole.left.row(y), 128)) << y;
    EXPECT_TRUE(same_row(row.elevation, whole.elevation.row(y), 128)) << y;
    EXPECT_TRUE(same_row(row.range, whole.range.row(y), 128)) << y;
  }
  EXPECT_FALSE(rows.row(100).known(5)); // NaN, zero and negative disparities give no point
  EXPECT_FALSE(rows.row(100).known(7));
  EXPECT_TRUE(rows.row(100).known(8));
}

TEST(RecomputedTerrain, EveryRowWorkedOutIsReportedEachTime) {
  const imaging::StereoRig rig = rig_of_side(64);
  imaging::Image<float> disparity(64, 64, 1, kInf);
  for (int v = 0; v < 64; ++v)
    for (int u = 0; u < v; ++u) // row v holds v points
      disparity(u, v) = 12.0F;
  Tally tally;
  const RecomputedTerrain rows(disparity, rig, {}, 2016, tally);
  rows.row(10);
  rows.row(10); // the row in hand: not worked out again
  EXPECT_EQ(tally.counts.count(Work::range_pixel), 10U);
  rows.row(20);
  rows.row(10);
  EXPECT_EQ(tally.counts.count(Work::range_pixel), 10U + 20U + 10U);
  EXPECT_EQ(tally.counts.count(Work::elevation_pixel), 40U);
  EXPECT_EQ(tally.counts.total(), 80U);
}

TEST(CountTerrainPoints, CountsAndReportsAsReconstructTerrainDoes) {
  const imaging::StereoRig rig = rig_of_side(128);
  const imaging::Image<float> disparity = wall_scene(rig);
  CountingMeter whole_work;
  const TerrainPoints whole = reconstruct_terrain(disparity, rig, {}, whole_work);
  CountingMeter counted_work;
  EXPECT_EQ(
      count_terrain_points(disparity, rig, {}, counted_work, std::pmr::get_default_resource()),
      whole.known_pixels);
  EXPECT_EQ(counted_work.count(Work::range_pixel), whole_work.count(Work::range_pixel));
  EXPECT_EQ(counted_work.count(Work::elevation_pixel), whole_work.count(Work::elevation_pixel));
}

TEST(RecomputedTerrain, RefusesADisparityThatDoesNotFitTheRig) {
  const imaging::StereoRig rig = rig_of_side(64);
  const imaging::Image<float> disparity(32, 64, 1, 5.0F);
  Tally tally;
  EXPECT_THROW(RecomputedTerrain(disparity, rig, {}, 0, tally), std::invalid_argument);
}

TEST(RecomputedTerrain, ZonesPathAndGroundPathAreThoseOfTheWholeMaps) {
  const imaging::StereoRig rig = rig_of_side(128);
  const imaging::Image<float> disparity = wall_scene(rig);
  const TerrainPoints whole = reconstruct_terrain(disparity, rig, {});
  Tally tally;
  const RecomputedTerrain rows(disparity, rig, {}, whole.known_pixels, tally);
  const ZoneOptions zone_options;
  CountingMeter whole_work;
  CountingMeter row_work;
  ZoneMap zones = find_zones(whole, {}, zone_options, whole_work);
  ZoneMap row_zones = find_zones(rows, {}, zone_options, row_work);
  EXPECT_EQ(row_zones.zone, zones.zone);
  EXPECT_EQ(row_zones.counts, zones.counts);
  EXPECT_GT(zones.count(Zone::traversable), 0U);
  EXPECT_GT(zones.count(Zone::step), 0U) << "the wall";
  EXPECT_GT(zones.count(Zone::margin), 0U);
  PlannerOptions planner;
  planner.target_min_m = 6.0;
  planner.target_max_m = 8.0;
  const PathPlan plan = plan_cycle_path(whole, zones, planner, {}, {}, whole_work);
  const PathPlan row_plan = plan_cycle_path(rows, row_zones, planner, {}, {}, row_work);
  EXPECT_EQ(row_plan.found, plan.found);
  EXPECT_EQ(row_plan.reason, plan.reason);
  EXPECT_EQ(row_plan.pixels, plan.pixels);
  EXPECT_TRUE(plan.found) << plan.reason;
  if (plan.found) {
    const auto ground = ground_path(whole, plan.pixels);
    const auto row_ground = ground_path(rows, plan.pixels);
    ASSERT_EQ(row_ground.size(), ground.size());
    for (std::size_t i = 0; i < ground.size(); ++i)
      EXPECT_EQ(row_ground[i], ground[i]) << i;
  }
  // The rules' own work is the same; working the rows out again is counted apart, and every
  // pass of the zones over the rows (at least five) works out every known point again.
  for (std::size_t k = 0; k < kWorkKinds; ++k)
    EXPECT_EQ(row_work.count(static_cast<Work>(k)), whole_work.count(static_cast<Work>(k)))
        << to_string(static_cast<Work>(k));
  EXPECT_GE(tally.counts.count(Work::range_pixel), 5 * whole.known_pixels);
}

} // namespace
} // namespace marsokhod::nav
