// The ground grid in strips along the forward axis: every strip width gives the zones of the
// whole grid, with the whole grid's work, and the halo's work reported apart.

#include "nav/terrain_grid.hpp"

#include "marsokhod/nav/zones/zones.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory_resource>

namespace marsokhod::nav {
namespace {

using testing::grid_terrain;
using testing::GridSpec;

/// Counts what the strips report as done again.
class StripTally final : public DynamicMeter {
public:
  void operator()(Work kind, std::uint64_t count) override { counts(kind, count); }
  CountingMeter counts;
};

// A map-like view 6.4 m deep (64 cells of 0.1 m along the forward axis) with a 0.5 m box, a
// ramp steeper than the slope limit and a low bump: steps, slopes, margins and free ground, at
// forward distances that cross many strip edges.
TerrainPoints varied_ground() {
  const GridSpec g{48, 128, 0.05, 2.0};
  return grid_terrain(g, [](double forward, double left) {
    if (forward > 3.0 && forward < 3.4 && left > 0.1 && left < 0.5)
      return 0.5; // a box
    if (forward > 5.0 && forward < 6.0)
      return (forward - 5.0) * 0.7; // 35 degrees
    if (forward > 7.0)
      return 0.7 + 0.1 * std::sin(3.0 * left); // a plateau with a gentle bump
    return forward > 6.0 ? 0.7 : 0.0;
  });
}

TEST(ZoneStrips, EveryStripWidthGivesTheWholeGridsZonesAndWork) {
  const TerrainPoints terrain = varied_ground();
  const ResidentTerrain rows(terrain);
  const ZoneOptions options;
  CountingMeter whole_work;
  const ZoneMap whole = find_zones(rows, {}, options, whole_work);
  ASSERT_GT(whole.count(Zone::step), 0U);
  ASSERT_GT(whole.count(Zone::slope), 0U);
  ASSERT_GT(whole.count(Zone::margin), 0U);
  ASSERT_GT(whole.count(Zone::traversable), 0U);
  for (const int cells : {1, 2, 7, 16, 33, 64, 1000}) {
    CountingMeter work;
    StripTally halo;
    const ZoneMap strips = find_zones(rows, {}, options, work, std::pmr::get_default_resource(),
                                      ZoneStrips{cells, 0, &halo});
    EXPECT_EQ(strips.zone, whole.zone) << cells << " cells a strip";
    EXPECT_EQ(strips.counts, whole.counts) << cells;
    EXPECT_EQ(work.count(Work::hazard_test), whole_work.count(Work::hazard_test)) << cells;
    EXPECT_EQ(halo.counts.total(), halo.counts.count(Work::hazard_test)) << cells;
    // A strip narrower than the grid (of about 80 columns) reads a halo around it.
    EXPECT_TRUE(cells >= 64 || halo.counts.total() > 0) << cells;
    EXPECT_TRUE(cells < 1000 || halo.counts.total() == 0) << cells;
  }
}

TEST(ZoneStrips, NarrowerStripsDoMoreAgain) {
  const TerrainPoints terrain = varied_ground();
  const ResidentTerrain rows(terrain);
  std::uint64_t previous = 0;
  for (const int cells : {32, 16, 8, 4}) {
    CountingMeter work;
    StripTally halo;
    find_zones(rows, {}, ZoneOptions{}, work, std::pmr::get_default_resource(),
               ZoneStrips{cells, 0, &halo});
    EXPECT_GT(halo.counts.total(), previous) << cells;
    previous = halo.counts.total();
  }
}

/// The largest number of bytes held at once.
class PeakMemory final : public std::pmr::memory_resource {
public:
  std::size_t peak = 0;

private:
  void* do_allocate(std::size_t bytes, std::size_t alignment) override {
    held_ += bytes;
    peak = std::max(peak, held_);
    return std::pmr::new_delete_resource()->allocate(bytes, alignment);
  }
  void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    held_ -= bytes;
    std::pmr::new_delete_resource()->deallocate(p, bytes, alignment);
  }
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }
  std::size_t held_ = 0;
};

std::size_t peak_of(const ResidentTerrain& rows, ZoneStrips strips, ZoneMap* out = nullptr) {
  PeakMemory memory;
  CountingMeter work;
  {
    const ZoneMap zones = find_zones(rows, {}, ZoneOptions{}, work, &memory, strips);
    if (out != nullptr)
      *out = zones; // copied onto the default memory
  }
  return memory.peak;
}

TEST(ZoneStrips, ABudgetOfBytesGivesStripsTheGridOfWhichFitsIt) {
  const TerrainPoints terrain = varied_ground();
  const ResidentTerrain rows(terrain);
  const ZoneMap whole = find_zones(rows, {}, ZoneOptions{});
  // One own column a strip: what the zones hold besides the grid, plus the smallest grid.
  const std::size_t least = peak_of(rows, ZoneStrips{0, 1, nullptr});
  for (const std::size_t budget : {std::size_t{20'000}, std::size_t{40'000}, std::size_t{80'000}}) {
    ZoneMap zones;
    const std::size_t peak = peak_of(rows, ZoneStrips{0, budget, nullptr}, &zones);
    EXPECT_EQ(zones.zone, whole.zone) << budget;
    EXPECT_LE(peak, least + budget) << budget;
  }
  EXPECT_LT(least, peak_of(rows, ZoneStrips{}));
}

} // namespace
} // namespace marsokhod::nav
