// Tests: the safest path planner against Dijkstra and on hand-made terrain.

#include "nav/portable_random.hpp"
#include "nav/terrain_grid.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav/path/path_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <queue>
#include <random>
#include <vector>

namespace marsokhod::nav {
namespace {

using testing::grid_forward;
using testing::grid_left;
using testing::grid_terrain;
using testing::GridSpec;
using testing::long_grid;

using test_support::kInfinity;

ZoneMap all_traversable(const TerrainPoints& t) {
  ZoneMap zones{imaging::Image<std::uint8_t>(t.width(), t.height(), 1, 0), {}};
  zones.counts[0] = static_cast<std::uint64_t>(t.width()) * t.height();
  return zones;
}

void prohibit(ZoneMap& zones, int x, int y, Zone zone = Zone::step) {
  zones.zone(x, y) = static_cast<std::uint8_t>(zone);
}

// Rows from..to - 1 across the whole view, column x given zone_of(x).
template <class ZoneOfColumn>
void prohibit_rows(ZoneMap& zones, int from, int to, ZoneOfColumn zone_of) {
  for (int y = from; y < to; ++y)
    for (int x = 0; x < zones.width(); ++x)
      prohibit(zones, x, y, zone_of(x));
}
void prohibit_rows(ZoneMap& zones, int from, int to, Zone zone) {
  prohibit_rows(
      zones, from, to, [zone](int) { return zone; });
}

// The documented edge weight, written out again:
// max(0, |H_i - H_j| - tolerance) + w * ground distance.
double edge(const TerrainPoints& t, int xa, int ya, int xb, int yb, const EdgeWeights& weights) {
  const double difference = std::abs(double{t.elevation(xb, yb)} - double{t.elevation(xa, ya)});
  const double climb =
      difference > weights.flat_tolerance_m ? difference - weights.flat_tolerance_m : 0.0;
  const double run = std::hypot(double{t.forward(xb, yb)} - t.forward(xa, ya),
                                double{t.left(xb, yb)} - t.left(xa, ya));
  return climb + weights.length_weight * run;
}

// A general Dijkstra over the same graph (edges from row y+1 to the three pixels above), with
// a binary heap and no knowledge of the rows' order.
std::vector<double> dijkstra(const TerrainPoints& t, const ZoneMap& zones, PixelPoint start,
                             const EdgeWeights& weights) {
  const int w = t.width();
  std::vector<double> distance(static_cast<std::size_t>(w) * t.height(), kInfinity);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  distance[start.y * w + start.x] = 0.0;
  heap.push({0.0, start.y * w + start.x});
  while (!heap.empty()) {
    const auto [d, node] = heap.top();
    heap.pop();
    if (d > distance[node])
      continue;
    const int x = node % w;
    const int y = node / w;
    for (int dx = -1; dx <= 1 && y > 0; ++dx) {
      const int nx = x + dx;
      const int ny = y - 1;
      if (nx < 0 || nx >= w || !zones.traversable(nx, ny))
        continue;
      const double candidate = d + edge(t, x, y, nx, ny, weights);
      if (candidate < distance[ny * w + nx]) {
        distance[ny * w + nx] = candidate;
        heap.push({candidate, ny * w + nx});
      }
    }
  }
  return distance;
}

using testing::unit;

TEST(SweepRows, GivesTheSameCostsAsDijkstraOnRandomGraphs) {
  std::mt19937_64 random(20240607);
  for (int trial = 0; trial < 40; ++trial) {
    const GridSpec g{3 + static_cast<int>(random() % 30), 2 + static_cast<int>(random() % 30), 0.05,
                     2.0};
    TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
    ZoneMap zones = all_traversable(t);
    const double blocked = 0.4 * unit(random);
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        t.elevation(x, y) = static_cast<float>(2.0 * unit(random));
        t.forward(x, y) += static_cast<float>(0.04 * unit(random));
        t.left(x, y) += static_cast<float>(0.04 * unit(random));
        if (unit(random) < blocked)
          prohibit(zones, x, y);
      }
    const PixelPoint start{static_cast<int>(random() % g.width), g.height - 1};
    zones.zone(start.x, start.y) = 0;
    const EdgeWeights weights{unit(random), 0.5 * unit(random)};
    const RowSweep sweep = sweep_rows(t, zones, start, 0, weights);
    const std::vector<double> expected = dijkstra(t, zones, start, weights);
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        const double want = expected[y * g.width + x];
        if (std::isinf(want))
          ASSERT_TRUE(std::isinf(sweep.cost(x, y))) << trial << ": " << x << "," << y;
        else
          ASSERT_NEAR(sweep.cost(x, y), want, 1e-5 * (1.0 + want))
              << trial << ": " << x << "," << y;
      }
  }
}

TEST(PlanPath, OnFlatGroundGoesStraightToTheNearestPointOfTheTargetRange) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  const PathPlan plan = plan_path(t, all_traversable(t), PlannerOptions{});
  ASSERT_TRUE(plan.found) << plan.reason;
  const int centre = (g.width - 1) / 2; // lateral offset 0
  EXPECT_EQ(plan.start, (PixelPoint{centre, g.height - 1}));
  // 10.0 m is row 207 - 160 = 47.
  EXPECT_EQ(plan.target, (PixelPoint{centre, 47}));
  for (const PixelPoint& p : plan.pixels)
    ASSERT_EQ(p.x, centre);
  EXPECT_EQ(plan.pixels.size(), 161U);
  EXPECT_NEAR(plan.cost, 0.02 * 8.0, 1e-4); // only the tie-break: 8 m of straight ground
  EXPECT_NEAR(plan.score, plan.cost, 1e-9);
}

TEST(PlanPath, PathCostIsTheSumOfItsEdgeWeights) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double forward, double left) {
    return 0.1 * std::sin(3.0 * forward) + 0.05 * std::cos(5.0 * left);
  });
  const PlannerOptions options;
  const PathPlan plan = plan_path(t, all_traversable(t), options);
  ASSERT_TRUE(plan.found) << plan.reason;
  const EdgeWeights weights = edge_weights(options);
  double sum = 0.0;
  for (std::size_t i = 1; i < plan.pixels.size(); ++i) {
    const PixelPoint a = plan.pixels[i - 1];
    const PixelPoint b = plan.pixels[i];
    ASSERT_EQ(b.y, a.y - 1);
    ASSERT_LE(std::abs(b.x - a.x), 1);
    sum += edge(t, a.x, a.y, b.x, b.y, weights);
  }
  EXPECT_NEAR(plan.cost, sum, 1e-4);
}

TEST(PlanPath, GoesThroughTheGapInAWall) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  ZoneMap zones = all_traversable(t);
  // A wall across the view 5 m ahead (row 147) with a gap at columns 30-32.
  for (int x = 0; x < g.width; ++x)
    if (x < 30 || x > 32)
      prohibit(zones, x, 147);
  const PathPlan plan = plan_path(t, zones, PlannerOptions{});
  ASSERT_TRUE(plan.found) << plan.reason;
  for (const PixelPoint& p : plan.pixels)
    ASSERT_TRUE(zones.traversable(p.x, p.y)) << p.x << "," << p.y;
  const PixelPoint crossing = plan.pixels[static_cast<std::size_t>(g.height - 1 - 147)];
  EXPECT_EQ(crossing.y, 147);
  EXPECT_GE(crossing.x, 30);
}

TEST(PlanPath, MissionHeadingPullsTheDestinationToItsSide) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  PlannerOptions options;
  options.heading_deg = 10.0; // to the left: columns left of the centre
  const PathPlan left = plan_path(t, all_traversable(t), options);
  options.heading_deg = -10.0;
  const PathPlan right = plan_path(t, all_traversable(t), options);
  ASSERT_TRUE(left.found && right.found);
  EXPECT_GT(t.left(left.target.x, left.target.y), 0.5);
  EXPECT_LT(t.left(right.target.x, right.target.y), -0.5);
}

TEST(PlanPath, StartsAtTheNearestTraversablePointInFront) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  ZoneMap zones = all_traversable(t);
  // The first 0.9 m in front is the margin of rocks to the sides: rows 207..190 (2.00..2.85 m).
  prohibit_rows(zones, 190, g.height, Zone::margin);
  const PathPlan plan = plan_path(t, zones, PlannerOptions{});
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_EQ(plan.start, (PixelPoint{20, 189}));
  EXPECT_NEAR(grid_forward(g, 189), 2.90, 1e-9); // fig. 4's start distance
  EXPECT_NEAR(grid_left(g, 20), 0.0, 1e-9);
}

TEST(PlanPath, TakesNoStartBehindAStepStraightAhead) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  // A rock 2.00-2.35 m ahead (rows 207..200) spanning the centre column, the ground beyond it
  // open: the nearest traversable point in front lies behind the rock.
  ZoneMap rock = all_traversable(t);
  prohibit_rows(rock, 200, g.height, [](int x) { return x == 20 ? Zone::step : Zone::margin; });
  const PathPlan blocked = plan_path(t, rock, PlannerOptions{});
  EXPECT_FALSE(blocked.found);
  EXPECT_NE(blocked.reason.find("step or slope 2.00 m straight ahead"), std::string::npos)
      << blocked.reason;
  // The same rock 0.30 m to the side (column 26) is outside the 0.25 m the start is sought in:
  // the start is the nearest traversable point straight ahead, 2.40 m away.
  ZoneMap aside = all_traversable(t);
  prohibit_rows(aside, 200, g.height, [](int x) { return x == 26 ? Zone::step : Zone::margin; });
  const PathPlan beside = plan_path(t, aside, PlannerOptions{});
  ASSERT_TRUE(beside.found) << beside.reason;
  EXPECT_EQ(beside.start, (PixelPoint{20, 199}));
}

TEST(PlanPath, TriesTheNextStartBeyondADeadEndInFront) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  // Open ground 2.00-2.35 m ahead (rows 207..200), closed across the whole view by a margin
  // 2.40-2.85 m ahead (rows 199..190), open again beyond: the nearest start leads nowhere.
  ZoneMap zones = all_traversable(t);
  prohibit_rows(zones, 190, 200, Zone::margin);
  PlannerOptions nearest_only;
  nearest_only.start_attempts = 1;
  const PathPlan dead_end = plan_path(t, zones, nearest_only);
  EXPECT_FALSE(dead_end.found);
  EXPECT_NE(dead_end.reason.find("can be reached from the start 2.00 m ahead"), std::string::npos)
      << dead_end.reason;
  // The next start is the nearest point in front above the rows the first sweep reached.
  const PathPlan plan = plan_path(t, zones, PlannerOptions{});
  ASSERT_TRUE(plan.found) << plan.reason;
  EXPECT_EQ(plan.start, (PixelPoint{20, 189}));
  EXPECT_EQ(plan.target, (PixelPoint{20, 47}));
  EXPECT_NEAR(plan.cost, 0.02 * 7.1, 1e-4); // 2.90 m to 10.0 m of straight level ground
}

TEST(PlanPath, ReportsWhyThereIsNoPath) {
  const GridSpec g = long_grid();
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  ZoneMap blocked_front = all_traversable(t);
  prohibit_rows(blocked_front, 150, g.height, Zone::step);
  const PathPlan no_start = plan_path(t, blocked_front, PlannerOptions{});
  EXPECT_FALSE(no_start.found);
  EXPECT_NE(no_start.reason.find("in front of the rover"), std::string::npos) << no_start.reason;

  ZoneMap wall = all_traversable(t);
  for (int x = 0; x < g.width; ++x)
    prohibit(wall, x, 100);
  const PathPlan no_target = plan_path(t, wall, PlannerOptions{});
  EXPECT_FALSE(no_target.found);
  EXPECT_NE(no_target.reason.find("can be reached"), std::string::npos) << no_target.reason;
  EXPECT_TRUE(no_target.pixels.empty());
}

TEST(PlanPath, NeverCrossesUnseenGroundLongerThanTheLimit) {
  // Rows 0..100 see level ground 1 m farther than the grid: between rows 101 and 100 lie
  // 1.05 m of ground no pixel sees (behind a crater rim, say).
  const GridSpec g = long_grid();
  TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  for (int y = 0; y <= 100; ++y)
    for (int x = 0; x < g.width; ++x) {
      t.forward(x, y) += 1.0F;
      t.range(x, y) = static_cast<float>(std::hypot(t.forward(x, y), t.left(x, y)));
    }
  PlannerOptions options;
  options.max_edge_m = 0.6;
  const PathPlan blocked = plan_path(t, all_traversable(t), options);
  EXPECT_FALSE(blocked.found);
  EXPECT_NE(blocked.reason.find("can be reached"), std::string::npos) << blocked.reason;
  options.max_edge_m = 1.1;
  const PathPlan crossing = plan_path(t, all_traversable(t), options);
  ASSERT_TRUE(crossing.found) << crossing.reason;
  EXPECT_NEAR(crossing.cost, 0.02 * 8.0, 1e-4); // 8 m of level ground, the gap included
}

TEST(PlanPath, ReportsOneRelaxationPerEdgeIntoTheReachableCone) {
  // From one start every row k above it has 2k + 1 reachable pixels; each of row k-1's 2k - 1
  // pixels feeds three pixels above, so rows 1..K examine 3 (1 + 3 + ... + 2K - 1) = 3 K^2
  // edges. The planner sweeps up to the highest target row (10.0..12.0 m: K = 200 rows).
  const GridSpec g{501, 208, 0.05, 2.0};
  const TerrainPoints t = grid_terrain(g, [](double, double) { return 0.0; });
  CountingMeter meter;
  PlannerOptions options;
  options.target_max_m = 12.0;
  const PathPlan plan = plan_path(t, all_traversable(t), options, meter);
  ASSERT_TRUE(plan.found);
  const std::uint64_t k = 207 - 7; // 12.0 m is row 207 - 200 = 7
  EXPECT_EQ(meter.count(Work::path_relaxation), 3 * k * k);
  EXPECT_EQ(meter.count(Work::path_backtrack), plan.pixels.size());
}

TEST(PlanPath, RejectsBadOptions) {
  const TerrainPoints t = grid_terrain(GridSpec{}, [](double, double) { return 0.0; });
  PlannerOptions reversed;
  reversed.target_min_m = 12.0;
  reversed.target_max_m = 10.0;
  EXPECT_THROW(plan_path(t, all_traversable(t), reversed), std::invalid_argument);
  PlannerOptions negative;
  negative.length_weight = -1.0;
  EXPECT_THROW(plan_path(t, all_traversable(t), negative), std::invalid_argument);
  PlannerOptions no_edge;
  no_edge.max_edge_m = 0.0;
  EXPECT_THROW(plan_path(t, all_traversable(t), no_edge), std::invalid_argument);
  PlannerOptions no_start;
  no_start.start_attempts = 0;
  EXPECT_THROW(plan_path(t, all_traversable(t), no_start), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::nav
