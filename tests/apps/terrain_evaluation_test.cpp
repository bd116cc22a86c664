#include "nav/terrain_grid.hpp"
#include "support/run_marsokhod.hpp"
#include "terrain_scoring.hpp"

#include "marsokhod/imaging/image/image_io.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace marsokhod::apps {
namespace {

using marsokhod::testing::run_marsokhod;

// A 4 x 1 strip: every pixel seen by both cameras, 5 m away (band 2-6 m).
world::GroundTruth strip_truth() {
  world::GroundTruth truth = world::GroundTruth::unknown(4, 1);
  for (int x = 0; x < 4; ++x) {
    truth.range(x, 0) = 5.0F;
    truth.visible(x, 0) = truth.valid(x, 0) = 255;
  }
  return truth;
}

nav::ZoneMap strip_zones(std::initializer_list<nav::Zone> zones) {
  nav::ZoneMap map{imaging::Image<std::uint8_t>(4, 1), {}};
  int x = 0;
  for (const nav::Zone z : zones)
    map.zone(x++, 0) = static_cast<std::uint8_t>(z);
  return map;
}

TEST(ScoreZones, CountsObstaclesProhibitedAndFreeGroundProhibitedByBand) {
  world::GroundTruth truth = strip_truth();
  truth.obstacles(0, 0) = truth.obstacles(1, 0) = 255;
  // Pixel 0: an obstacle we prohibit by its margin; 1: an obstacle we miss; 2: free ground we
  // prohibit; 3: free ground we leave open.
  const nav::ZoneMap ours = strip_zones(
      {nav::Zone::margin, nav::Zone::traversable, nav::Zone::step, nav::Zone::traversable});
  const nav::ZoneMap theirs = strip_zones(
      {nav::Zone::step, nav::Zone::step, nav::Zone::traversable, nav::Zone::traversable});
  const BandTable table = score_zones(ours, theirs, truth);
  EXPECT_EQ(table[0].obstacle_pixels, 2U);
  EXPECT_EQ(table[0].obstacles_prohibited, 1U);
  EXPECT_EQ(table[0].free_pixels, 2U);
  EXPECT_EQ(table[0].free_prohibited, 1U);
  EXPECT_EQ(table[0].free_prohibited_as[static_cast<std::size_t>(nav::Zone::step)], 1U);
  EXPECT_EQ(table[0].free_prohibited_as[static_cast<std::size_t>(nav::Zone::margin)], 0U);
  EXPECT_EQ(table[1].obstacle_pixels + table[2].free_pixels, 0U);
  // The detector alone: the margin is no hazard.
  const BandTable hazards = score_hazards(ours, truth);
  EXPECT_EQ(hazards[0].obstacles_prohibited, 0U);
  EXPECT_EQ(hazards[0].free_prohibited, 1U);
}

TEST(ScoreZones, FreeGroundInsideTheTruthsMarginAndPixelsOneCameraMissesAreNotScored) {
  world::GroundTruth truth = strip_truth();
  truth.valid(3, 0) = 0; // occluded from the right camera
  const nav::ZoneMap ours =
      strip_zones({nav::Zone::step, nav::Zone::step, nav::Zone::step, nav::Zone::step});
  const nav::ZoneMap theirs = strip_zones(
      {nav::Zone::margin, nav::Zone::traversable, nav::Zone::traversable, nav::Zone::traversable});
  const BandTable table = score_zones(ours, theirs, truth);
  EXPECT_EQ(table[0].free_pixels, 2U);
  EXPECT_EQ(table[0].free_prohibited, 2U);
}

TEST(GroundTruthZones, GroundOnlyOneCameraSeesIsUnknownAndObstaclesAreSteps) {
  world::GroundTruth truth = strip_truth();
  truth.valid(2, 0) = 0; // the left camera sees it, the right one does not
  truth.obstacles(0, 0) = 255;
  nav::TerrainPoints terrain{imaging::Image<float>(4, 1, 1, 5.0F), imaging::Image<float>(4, 1, 1, 0.0F),
                             imaging::Image<float>(4, 1, 1, 0.0F), imaging::Image<float>(4, 1, 1, 5.0F), 4};
  for (int x = 0; x < 4; ++x)
    terrain.left(x, 0) = 0.4F * static_cast<float>(x); // 0.4 m apart: beyond each other's margin
  nav::ZoneOptions options;
  options.rover_half_width_m = 0.3;
  const nav::ZoneMap zones = ground_truth_zones(terrain, truth, options);
  EXPECT_EQ(zones.at(0, 0), nav::Zone::step);
  EXPECT_EQ(zones.at(1, 0), nav::Zone::traversable);
  EXPECT_EQ(zones.at(2, 0), nav::Zone::unknown);
  EXPECT_EQ(zones.at(3, 0), nav::Zone::traversable);
}

TEST(ElevationErrors, AreTakenOnJudgedFreeGroundWhereTheNavigationHasAPoint) {
  world::GroundTruth truth = strip_truth();
  truth.range(3, 0) = 7.0F; // band 6-10 m
  truth.obstacles(1, 0) = 255;
  const float kInf = std::numeric_limits<float>::infinity();
  nav::TerrainPoints ours{imaging::Image<float>(4, 1), imaging::Image<float>(4, 1), imaging::Image<float>(4, 1),
                          imaging::Image<float>(4, 1), 3};
  for (int x = 0; x < 4; ++x) {
    truth.elevation(x, 0) = 0.10F;
    ours.elevation(x, 0) = 0.10F + 0.01F * static_cast<float>(x + 1);
  }
  ours.elevation(2, 0) = kInf; // no point: not scored
  nav::ZoneMap zones{imaging::Image<std::uint8_t>(4, 1, 1, 0), {}};
  std::array<std::vector<float>, kTerrainBands.size()> errors;
  collect_elevation_errors(ours, zones, truth, errors);
  // Pixel 0 (0.01 m off) in 2-6 m; pixel 1 is an obstacle; pixel 3 (0.04 m off) in 6-10 m.
  ASSERT_EQ(errors[0].size(), 1U);
  EXPECT_NEAR(errors[0][0], 0.01, 1e-6);
  ASSERT_EQ(errors[1].size(), 1U);
  EXPECT_NEAR(errors[1][0], 0.04, 1e-6);
  EXPECT_TRUE(errors[2].empty());
  // A point the zone rules set aside as unknown (out of order, say) is not scored.
  zones.zone(3, 0) = static_cast<std::uint8_t>(nav::Zone::unknown);
  std::array<std::vector<float>, kTerrainBands.size()> judged;
  collect_elevation_errors(ours, zones, truth, judged);
  EXPECT_EQ(judged[0].size(), 1U);
  EXPECT_TRUE(judged[1].empty());
}

// A 5 x 10 view of level ground, 0.1 m a pixel: row 9 is 2.0 m ahead, row 0 2.9 m; column 2
// straight ahead. The path starts 2.5 m ahead (row 4) and runs straight on.
struct StraightAhead {
  nav::testing::GridSpec grid{5, 10, 0.1, 2.0};
  nav::TerrainPoints terrain = nav::testing::grid_terrain(grid, [](double, double) { return 0.0; });
  world::GroundTruth truth = world::GroundTruth::unknown(5, 10);
  nav::PathPlan plan;
  StraightAhead() {
    plan.start = {2, 4};
    plan.pixels = {{2, 4}, {2, 3}, {2, 2}, {2, 1}, {2, 0}};
  }
};

TEST(CrossesObstacle, IsTrueWhenAnyPathPixelSeesAnObstacle) {
  StraightAhead site;
  EXPECT_FALSE(crosses_obstacle(site.plan, site.terrain, site.truth));
  site.truth.obstacles(2, 1) = 255;
  EXPECT_TRUE(crosses_obstacle(site.plan, site.terrain, site.truth));
}

TEST(CrossesObstacle, IsTrueWhenTheDriveToTheStartSeesAnObstacle) {
  StraightAhead site;
  // 0.2 m beside the line from the rover to the start: the rover's centre passes it by.
  site.truth.obstacles(0, 7) = 255;
  EXPECT_FALSE(crosses_obstacle(site.plan, site.terrain, site.truth));
  // 2.2 m straight ahead, short of the start: the rover drives over it to reach the start.
  site.truth.obstacles(2, 7) = 255;
  EXPECT_TRUE(crosses_obstacle(site.plan, site.terrain, site.truth));
  // Where the true terrain has no point at the start, only the path's own pixels count.
  site.terrain.elevation(2, 4) = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(crosses_obstacle(site.plan, site.terrain, site.truth));
}

TEST(Percent, IsNotANumberForAnEmptyWhole) {
  EXPECT_DOUBLE_EQ(percent(1, 4), 25.0);
  EXPECT_TRUE(std::isnan(percent(0, 0)));
}

TEST(EvalTerrainCommand, ReportsEveryKeyForTwoSmallSites) {
  const auto result = run_marsokhod("eval terrain --seeds 3..4 --size 64 --terrain-size 16 --json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["seeds"], 2);
  for (const char* key :
       {"obstacle_recall", "false_prohibited", "false_prohibited_by_zone", "paths_found",
        "unsafe_paths", "ground_truth_paths", "bands", "hazard_bands", "per_seed"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["bands"].size(), 3U);
  EXPECT_EQ(json["bands"][0]["band_m"], "2-6");
  EXPECT_EQ(json["per_seed"].size(), 2U);
  EXPECT_NE(result.err.find("seed 2/2"), std::string::npos) << result.err;
}

TEST(EvalTerrainCommand, PicturesShowEachSiteInThreePanels) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "marsokhod-eval-terrain-tests" / "pictures";
  std::filesystem::remove_all(dir);
  const auto result = run_marsokhod("eval terrain --seeds 3 --size 64 --terrain-size 16 "
                                    "--pictures '" +
                                    dir.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const imaging::AnyImage picture = imaging::read_image(dir / "seed-3.png");
  const auto* rgb = std::get_if<imaging::Image<std::uint8_t>>(&picture);
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->width(), 3 * 64);
  EXPECT_EQ(rgb->height(), 64);
  EXPECT_EQ(rgb->channels(), 3);
}

TEST(EvalTerrainCommand, APicturesFolderThatCannotBeMadeIsARuntimeErrorNamingIt) {
  const std::filesystem::path base =
      std::filesystem::temp_directory_path() / "marsokhod-eval-terrain-tests" / "blocked";
  std::filesystem::create_directories(base);
  std::ofstream(base / "a-file") << "not a folder";
  const std::filesystem::path dir = base / "a-file" / "pictures";
  const auto result =
      run_marsokhod("eval terrain --seeds 3 --size 64 --pictures '" + dir.string() + "'");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(dir.string()), std::string::npos) << result.err;
}

TEST(EvalTerrainCommand, MalformedSeedRangesAreUsageErrors) {
  for (const std::string seeds : {"5..3", "abc", "1..", "-1..2"}) {
    const auto result = run_marsokhod("eval terrain --seeds " + seeds);
    EXPECT_EQ(result.exit_code, 2) << seeds;
    EXPECT_NE(result.err.find("--seeds"), std::string::npos) << result.err;
  }
}

} // namespace
} // namespace marsokhod::apps
