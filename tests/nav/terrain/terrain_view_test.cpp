// Tests: the level-ground view: seeable pixels, columns past the edge, ground disparity.

#include "nav/portable_random.hpp"
#include "support/test_files.hpp"
#include "terrain/terrain_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

// keep_seeable decides whole runs of a row from its two ends; it must keep exactly the pixels
// the per-pixel test keeps, for rising and falling rows, rows across the horizon and the sky.

namespace marsokhod::nav::detail {
namespace {

using test_support::kInf;

std::vector<float> tested_per_pixel(const std::vector<std::uint8_t>& seen, double first_d,
                                    double rise, std::vector<float> out) {
  const int width = static_cast<int>(out.size());
  const double span = std::max(width - 1.0, 1.0);
  for (int x = 0; x < width; ++x) {
    const double ground_d = first_d + rise * (x / span);
    if (seen[x] == 0 || ground_d <= 0.0 || x < ground_d)
      out[x] = kInf;
  }
  return out;
}

using testing::unit;

TEST(KeepSeeable, KeepsWhatThePerPixelTestKeeps) {
  std::mt19937_64 random(9127);
  for (int trial = 0; trial < 4000; ++trial) {
    const int width = 1 + static_cast<int>(random() % 300);
    const double scale = trial % 2 == 0 ? 40.0 : width * 1.5;
    double first_d = scale * (unit(random) - 0.2);
    double rise = scale * (unit(random) - 0.5);
    if (trial % 7 == 0)
      rise = 0.0;
    if (trial % 11 == 0)
      first_d = static_cast<double>(random() % 40);
    if (trial % 13 == 0)
      rise = static_cast<double>(random() % 9) - 4.0;
    if (trial % 17 == 0)
      first_d = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(width));
    std::vector<float> out(static_cast<std::size_t>(width));
    for (int x = 0; x < width; ++x) {
      seen[x] = random() % 5 == 0 ? 0 : 255;
      out[x] = static_cast<float>(unit(random));
    }
    const std::vector<float> want = tested_per_pixel(seen, first_d, rise, out);
    const std::pmr::vector<double> fractions =
        column_fractions(width, std::max(width - 1.0, 1.0), std::pmr::get_default_resource());
    std::vector<float> kept(static_cast<std::size_t>(width), kInf);
    keep_seeable(seen.data(), fractions.data(), first_d, rise, width, out.data(), kept.data());
    for (int x = 0; x < width; ++x)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(kept[x]), std::bit_cast<std::uint32_t>(want[x]))
          << trial << ": x " << x << " of " << width << ", first " << first_d << ", rise " << rise;
  }
}

TEST(ColumnsPastEdge, CountsTheColumnsWhoseLevelGroundLiesBeyondTheRightImage) {
  const std::pmr::vector<double> fractions =
      column_fractions(101, 100.0, std::pmr::get_default_resource());
  // Flat: x < 10.5 for x = 0..10.
  EXPECT_EQ(columns_past_edge(fractions.data(), 10.5, 0.0, 101), 11);
  // ground_d = 20 - 0.1 x: x < 20 - 0.1 x for x < 18.2, so x = 0..18.
  EXPECT_EQ(columns_past_edge(fractions.data(), 20.0, -10.0, 101), 19);
  // At or above the horizon: sky, none; the whole row when even the last column is short.
  EXPECT_EQ(columns_past_edge(fractions.data(), 0.0, 0.0, 101), 0);
  EXPECT_EQ(columns_past_edge(fractions.data(), -3.0, 1.0, 101), 0);
  EXPECT_EQ(columns_past_edge(fractions.data(), 150.0, 0.0, 101), 101);
}

TEST(LevelGround, GivesTheRigsGroundDisparity) {
  std::mt19937_64 random(4407);
  for (int trial = 0; trial < 50; ++trial) {
    imaging::RigParameters p;
    p.width_px = 16 + static_cast<int>(random() % 300);
    p.height_px = 16 + static_cast<int>(random() % 300);
    p.pitch_down_deg = 30.0 * unit(random) - 5.0;
    const imaging::StereoRig rig(p);
    const imaging::Attitude attitude{20.0 * unit(random) - 10.0, 20.0 * unit(random) - 10.0};
    const LevelGround ground(rig, attitude);
    for (int v = 0; v < rig.height(); v += 7)
      for (const double u : {0.0, rig.cx(), rig.width() - 1.0}) {
        const double want = rig.ground_disparity(u, v, attitude);
        ASSERT_EQ(std::bit_cast<std::uint64_t>(ground.disparity(u, v)),
                  std::bit_cast<std::uint64_t>(want))
            << trial << ": " << u << "," << v;
      }
  }
}

} // namespace
} // namespace marsokhod::nav::detail
