// The navigation program on the emulated network: the same results and the same work as the
// native cycle, clean memory faults, and the occam rule of one channel per link direction.

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>

namespace marsokhod::occam_port {
namespace {

const std::filesystem::path kPlatforms = std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms";

/// A textured pair whose right image is the left one shifted by a disparity that grows down the
/// rows, as level ground does; the stereo matcher has something to find everywhere.
struct SyntheticPair {
  imaging::Image<std::uint8_t> left{128, 128};
  imaging::Image<std::uint8_t> right{128, 128};
  imaging::StereoRig rig{imaging::RigParameters{}};

  explicit SyntheticPair(unsigned seed) {
    imaging::RigParameters parameters;
    parameters.width_px = parameters.height_px = 128;
    rig = imaging::StereoRig(parameters);
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> grey(0, 255);
    imaging::Image<std::uint8_t> texture(192, 128); // room for x + 20 + d, d at most 17
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 192; ++x)
        texture(x, y) = static_cast<std::uint8_t>(grey(random));
    for (int y = 0; y < 128; ++y) {
      const int d = 2 + y / 8;
      for (int x = 0; x < 128; ++x) {
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

TEST(NavigationProgram, GivesTheNativeCycleResultAndReportsTheSameWork) {
  const emulator::PlatformSpec card = emulator::load_platform(kPlatforms / "pc-card.toml");
  const Placement placement = everything_on("card", card.name);
  for (unsigned seed : {1U, 2U}) {
    const SyntheticPair pair(seed);
    nav::NavigationOptions options;
    nav::CountingMeter native_work;
    const nav::NavigationResult native =
        nav::navigate(pair.left, pair.right, pair.rig, options, native_work);
    const CycleInput input{pair.left, pair.right, &pair.rig, options};
    const CycleEmulation run =
        emulate_navigation_cycle(input, CycleSetup{&card, &placement, std::nullopt, nullptr});
    ASSERT_FALSE(run.memory_fault);
    ASSERT_TRUE(run.result);
    EXPECT_TRUE(same_floats(run.result->stereo.disparity, native.stereo.disparity));
    EXPECT_EQ(run.result->stereo.valid_pixels, native.stereo.valid_pixels);
    EXPECT_EQ(std::memcmp(run.result->zones.zone.data(), native.zones.zone.data(),
                          native.zones.zone.size()),
              0);
    EXPECT_EQ(run.result->found(), native.found());
    EXPECT_EQ(run.result->reason(), native.reason());
    EXPECT_EQ(run.result->plan.pixels, native.plan.pixels);
    for (std::size_t k = 0; k < nav::kWorkKinds; ++k) {
      const auto kind = static_cast<nav::Work>(k);
      EXPECT_EQ(run.work.count(kind), native_work.count(kind)) << nav::to_string(kind);
    }
    // The terrain is kept as the disparity: the zones and the path work its rows out again,
    // reported apart. Only the range and elevation of points are done again, and the zones'
    // passes over the rows (at least five) alone do each point again five times.
    const std::uint64_t points = native_work.count(nav::Work::range_pixel);
    EXPECT_GE(run.recomputed_work.count(nav::Work::range_pixel), 5 * points);
    EXPECT_EQ(run.recomputed_work.count(nav::Work::elevation_pixel),
              run.recomputed_work.count(nav::Work::range_pixel));
    EXPECT_EQ(run.recomputed_work.total(), 2 * run.recomputed_work.count(nav::Work::range_pixel));
    EXPECT_GT(run.emulated, 0);
  }
}

TEST(NavigationProgram, AMemoryFaultEndsTheRunWithTheNodeProcessAndBuffer) {
  const emulator::PlatformSpec card = emulator::load_platform(kPlatforms / "pc-card.toml");
  const Placement placement = everything_on("card", card.name);
  const SyntheticPair pair(3);
  const CycleInput input{pair.left, pair.right, &pair.rig, {}};
  CycleSetup setup{&card, &placement, std::nullopt, nullptr};
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
} // namespace marsokhod::occam_port
