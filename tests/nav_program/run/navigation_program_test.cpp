// The navigation program on the emulated network: the same results and the same work as the
// native cycle, clean memory faults, and the occam rule of one channel per link direction.

#include "support/test_files.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

namespace marsokhod::nav_program {
namespace {

using test_support::kPlatforms;

/// A textured pair whose right image is the left one shifted by a disparity that grows down the
/// rows, as level ground does; the stereo matcher has something to find everywhere.
struct SyntheticPair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
  imaging::StereoRig rig{imaging::RigParameters{}};

  explicit SyntheticPair(unsigned seed, int side = 128) : left(side, side), right(side, side) {
    imaging::RigParameters parameters;
    parameters.width_px = parameters.height_px = side;
    rig = imaging::StereoRig(parameters);
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> grey(0, 255);
    // Room for x + 20 + d, d at most 2 + (side - 1) / 8.
    imaging::Image<std::uint8_t> texture(side + 64, side);
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side + 64; ++x)
        texture(x, y) = static_cast<std::uint8_t>(grey(random));
    for (int y = 0; y < side; ++y) {
      const int d = 2 + y / 8;
      for (int x = 0; x < side; ++x) {
        left(x, y) = texture(x + 20, y);
        right(x, y) = texture(x + 20 + d, y);
      }
    }
  }
};

Placement everything_on(const std::string& node, const std::string& platform) {
  Placement placement;
  placement.source = "test placement";
  placement.platform = platform;
  for (const std::string& process : navigation_program_shape().processes)
    placement.places.push_back({process, node, 0});
  return placement;
}

bool same_floats(const imaging::Image<float>& a, const imaging::Image<float>& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

/// One pair run natively (counting its work) and on the PC card, every process on the card.
struct Compared {
  nav::CountingMeter native_work;
  nav::NavigationResult native;
  CycleEmulation run;
};

Compared on_the_card(const SyntheticPair& pair) {
  const emulator::PlatformSpec card = emulator::load_platform(kPlatforms / "pc-card.toml");
  const Placement placement = everything_on("card", card.name);
  const nav::NavigationOptions options;
  Compared compared;
  compared.native = nav::navigate(pair.left, pair.right, pair.rig, options, compared.native_work);
  const CycleInput input{pair.left, pair.right, &pair.rig, options, {}};
  compared.run =
      emulate_navigation_cycle(input, CycleSetup{&card, &placement, std::nullopt, nullptr,
                                                 kOccamStyleFactor, nullptr, std::nullopt});
  return compared;
}

void expect_the_native_work(const Compared& c) {
  for (std::size_t k = 0; k < nav::kWorkKinds; ++k) {
    const auto kind = static_cast<nav::Work>(k);
    EXPECT_EQ(c.run.work.count(kind), c.native_work.count(kind)) << nav::to_string(kind);
  }
}

TEST(NavigationProgram, GivesTheNativeCycleResultAndReportsTheSameWork) {
  for (unsigned seed : {1U, 2U}) {
    const Compared c = on_the_card(SyntheticPair(seed));
    const CycleEmulation& run = c.run;
    ASSERT_FALSE(run.memory_fault);
    ASSERT_TRUE(run.result);
    EXPECT_TRUE(same_floats(run.result->stereo.disparity, c.native.stereo.disparity));
    EXPECT_EQ(run.result->stereo.valid_pixels, c.native.stereo.valid_pixels);
    EXPECT_EQ(std::memcmp(run.result->zones.zone.data(), c.native.zones.zone.data(),
                          c.native.zones.zone.size()),
              0);
    EXPECT_EQ(run.result->found(), c.native.found());
    EXPECT_EQ(run.result->reason(), c.native.reason());
    EXPECT_EQ(run.result->plan.pixels, c.native.plan.pixels);
    expect_the_native_work(c);
    // The card's 2 MB keep the terrain's maps at 128 x 128: nothing is worked out again.
    EXPECT_TRUE(run.plan.terrain_kept);
    EXPECT_EQ(run.recomputed_work.total(), 0U);
    EXPECT_GT(run.emulated, 0);
  }
}

// The style factor multiplies the cycles of every unit of work and nothing else: the work
// itself, the links and the channels stay as they are.
TEST(NavigationProgram, TheOccamStyleScalesTheWorksCpuTimeAndNotTheWork) {
  const SyntheticPair pair(5);
  const emulator::PlatformSpec card = emulator::load_platform(kPlatforms / "pc-card.toml");
  const Placement placement = everything_on("card", card.name);
  const CycleInput input{pair.left, pair.right, &pair.rig, nav::NavigationOptions{}, {}};
  const CycleEmulation once = emulate_navigation_cycle(
      input, CycleSetup{&card, &placement, std::nullopt, nullptr, 1.0, nullptr, std::nullopt});
  const CycleEmulation twice = emulate_navigation_cycle(
      input, CycleSetup{&card, &placement, std::nullopt, nullptr, 2.0, nullptr, std::nullopt});
  for (std::size_t k = 0; k < nav::kWorkKinds; ++k)
    EXPECT_EQ(once.work.count(static_cast<nav::Work>(k)),
              twice.work.count(static_cast<nav::Work>(k)));
  for (std::size_t i = 0; i < once.processes.size(); ++i) {
    if (once.processes[i].name != "matching" && once.processes[i].name != "zones")
      continue;
    const double ratio =
        static_cast<double>(twice.processes[i].cpu) / static_cast<double>(once.processes[i].cpu);
    EXPECT_GT(ratio, 1.98) << once.processes[i].name;
    EXPECT_LE(ratio, 2.0) << once.processes[i].name;
  }
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_THROW(emulate_navigation_cycle(input, CycleSetup{&card, &placement, std::nullopt,
                                                            nullptr, bad, nullptr, std::nullopt}),
                 std::invalid_argument);
}

TEST(NavigationProgram, WhereTheTerrainMapsDoNotFitTheirRowsAreWorkedOutAgainAndReportedApart) {
  // At 256 x 256 the card's 2 MB cannot keep the four terrain maps beside the zones and the
  // path: the plan keeps the disparity, and the zones and the path work the rows out again.
  const Compared c = on_the_card(SyntheticPair(3, 256));
  const CycleEmulation& run = c.run;
  ASSERT_FALSE(run.memory_fault);
  ASSERT_TRUE(run.result);
  EXPECT_FALSE(run.plan.terrain_kept);
  EXPECT_TRUE(same_floats(run.result->terrain.range, c.native.terrain.range));
  EXPECT_EQ(std::memcmp(run.result->zones.zone.data(), c.native.zones.zone.data(),
                        c.native.zones.zone.size()),
            0);
  EXPECT_EQ(run.result->plan.pixels, c.native.plan.pixels);
  expect_the_native_work(c);
  // Only the range and elevation of points are done again, and the zones' passes over the
  // rows (at least five) alone do every point again five times.
  const std::uint64_t points = c.native_work.count(nav::Work::range_pixel);
  EXPECT_GT(points, 0U);
  EXPECT_GE(run.recomputed_work.count(nav::Work::range_pixel), 5 * points);
  EXPECT_EQ(run.recomputed_work.count(nav::Work::elevation_pixel),
            run.recomputed_work.count(nav::Work::range_pixel));
  EXPECT_EQ(run.recomputed_work.total(), 2 * run.recomputed_work.count(nav::Work::range_pixel));
}

TEST(NavigationProgram, AMemoryFaultEndsTheRunWithTheNodeProcessAndBuffer) {
  const emulator::PlatformSpec card = emulator::load_platform(kPlatforms / "pc-card.toml");
  const Placement placement = everything_on("card", card.name);
  const SyntheticPair pair(3);
  const CycleInput input{pair.left, pair.right, &pair.rig, {}, {}};
  CycleSetup setup{&card,   &placement,  std::nullopt, nullptr, kOccamStyleFactor,
                   nullptr, std::nullopt};
  setup.external_bytes = 64 * 1024;
  const CycleEmulation run = emulate_navigation_cycle(input, setup);
  ASSERT_TRUE(run.memory_fault);
  EXPECT_EQ(run.memory_fault->node, "card");
  EXPECT_FALSE(run.memory_fault->process.empty());
  EXPECT_FALSE(run.memory_fault->what.empty());
  EXPECT_GT(run.memory_fault->requested_bytes, run.memory_fault->largest_free_block);
  EXPECT_FALSE(run.result);
  // 64 KB external plus 4 KB on chip: no process can have held more.
  for (const ProcessFigures& process : run.processes)
    EXPECT_LE(process.peak_bytes, 68U * 1024) << process.name;
}

} // namespace
} // namespace marsokhod::nav_program
