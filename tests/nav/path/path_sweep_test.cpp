// Tests: the two-lane row sweep against a plain one-edge-at-a-time sweep, bit for bit.

#include "nav/portable_random.hpp"
#include "nav/terrain_grid.hpp"
#include "support/test_files.hpp"

#include "marsokhod/nav/path/path_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

// The sweep computes its edges two pixels at a time; its costs and predecessors must be, bit for
// bit, those of the plain one-edge-at-a-time sweep written out below.

namespace marsokhod::nav {
namespace {

using test_support::kInf;

struct Plain {
  std::vector<float> cost;
  std::vector<std::int8_t> from;
  std::uint64_t relaxations = 0;
};

double plain_edge(const TerrainPoints& t, int xb, int yb, int x, int y, const EdgeWeights& w) {
  const double ahead = static_cast<double>(t.forward(x, y)) - t.forward(xb, yb);
  const double across = static_cast<double>(t.left(x, y)) - t.left(xb, yb);
  const double squared = ahead * ahead + across * across;
  if (squared > w.max_edge_m * w.max_edge_m)
    return std::numeric_limits<double>::infinity();
  const double climb =
      std::max(0.0, std::abs(static_cast<double>(t.elevation(x, y)) - t.elevation(xb, yb)) -
                        w.flat_tolerance_m);
  return climb + w.length_weight * std::sqrt(squared);
}

Plain plain_sweep(const TerrainPoints& t, const ZoneMap& zones, PixelPoint start, int first_row,
                  const EdgeWeights& w) {
  const int width = t.width();
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y) * width + x; };
  Plain p{std::vector<float>(static_cast<std::size_t>(width) * t.height(), kInf),
          std::vector<std::int8_t>(static_cast<std::size_t>(width) * t.height(), kNoPredecessor)};
  p.cost[at(start.x, start.y)] = 0.0F;
  for (int y = start.y - 1; y >= first_row; --y)
    for (int x = 0; x < width; ++x) {
      if (!zones.traversable(x, y) || !std::isfinite(t.elevation(x, y)))
        continue;
      double best = std::numeric_limits<double>::infinity();
      for (const int step : {0, -1, 1}) {
        const int xb = x + step;
        if (xb < 0 || xb >= width || p.cost[at(xb, y + 1)] == kInf)
          continue;
        ++p.relaxations;
        const double candidate = p.cost[at(xb, y + 1)] + plain_edge(t, xb, y + 1, x, y, w);
        if (candidate < best) {
          best = candidate;
          p.from[at(x, y)] = static_cast<std::int8_t>(step);
        }
      }
      p.cost[at(x, y)] = static_cast<float>(best);
    }
  return p;
}

using testing::unit;

// Rough ground with holes (unknown points), prohibited pixels, odd and even widths and edge
// limits that cut some edges, so that every branch of the lanes is taken.
TEST(SweepRows, MatchesThePlainSweepBitForBit) {
  std::mt19937_64 random(77031);
  for (int trial = 0; trial < 60; ++trial) {
    const testing::GridSpec g{1 + static_cast<int>(random() % 40),
                              2 + static_cast<int>(random() % 40), 0.05, 2.0};
    TerrainPoints t = testing::grid_terrain(g, [](double, double) { return 0.0; });
    ZoneMap zones{imaging::Image<std::uint8_t>(g.width, g.height, 1, 0), {}};
    const double holes = 0.2 * unit(random);
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        t.elevation(x, y) = static_cast<float>(0.3 * unit(random));
        t.forward(x, y) += static_cast<float>(0.08 * unit(random));
        t.left(x, y) += static_cast<float>(0.08 * unit(random));
        if (unit(random) < holes)
          t.elevation(x, y) = t.forward(x, y) = t.left(x, y) = kInf;
        if (unit(random) < holes)
          zones.zone(x, y) = static_cast<std::uint8_t>(Zone::step);
      }
    const PixelPoint start{static_cast<int>(random() % g.width), g.height - 1};
    t.elevation(start.x, start.y) = 0.0F;
    t.forward(start.x, start.y) = t.left(start.x, start.y) = 0.0F;
    zones.zone(start.x, start.y) = 0;
    const EdgeWeights weights{unit(random), 0.1 * unit(random),
                              trial % 3 == 0 ? std::numeric_limits<double>::infinity()
                                             : 0.05 + 0.1 * unit(random)};
    const int first_row = static_cast<int>(random() % g.height);
    CountingMeter meter;
    const RowSweep sweep = sweep_rows(t, zones, start, first_row, weights, meter);
    const Plain want = plain_sweep(t, zones, start, first_row, weights);
    EXPECT_EQ(meter.count(Work::path_relaxation), want.relaxations) << trial;
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * g.width + x;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(sweep.cost(x, y)),
                  std::bit_cast<std::uint32_t>(want.cost[i]))
            << trial << ": " << x << "," << y;
        ASSERT_EQ(sweep.from(x, y), want.from[i]) << trial << ": " << x << "," << y;
      }
  }
}

} // namespace
} // namespace marsokhod::nav
