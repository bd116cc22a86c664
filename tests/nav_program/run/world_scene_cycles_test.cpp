// The emulated cycle against the native one on the world's scenes: for world seeds 1..20 at
// 128 and 256 pixels, on the PC card and on the onboard modules, the emulation either gives the
// native cycle's disparity, zones, path and drive commands bit for bit, or stops on a memory
// fault it reports. The card's 2 MB hold every cycle at both sizes (the terrain's maps at 128,
// the disparity at 256); the onboard modules' 256 KB hold every 128 x 128 cycle (the matcher's
// bands, the terrain as the disparity, the zones in strips).

#include "support/test_files.hpp"

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <tuple>

namespace marsokhod::nav_program {
namespace {

using test_support::kPlatforms;

bool same_bytes(const auto& a, const auto& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(*a.data())) == 0;
}

bool same_commands(const nav::DrivePlan& a, const nav::DrivePlan& b) {
  if (a.commands.size() != b.commands.size())
    return false;
  for (std::size_t i = 0; i < a.commands.size(); ++i)
    if (a.commands[i].turn_deg != b.commands[i].turn_deg ||
        a.commands[i].distance_m != b.commands[i].distance_m)
      return false;
  return true;
}

void expect_the_native_result(const nav::NavigationResult& emulated,
                              const nav::NavigationResult& native, const std::string& what) {
  EXPECT_TRUE(same_bytes(emulated.stereo.disparity, native.stereo.disparity)) << what;
  EXPECT_TRUE(same_bytes(emulated.zones.zone, native.zones.zone)) << what;
  EXPECT_EQ(emulated.found(), native.found()) << what;
  EXPECT_EQ(emulated.reason(), native.reason()) << what;
  EXPECT_EQ(emulated.plan.pixels, native.plan.pixels) << what;
  EXPECT_EQ(emulated.plan.cost, native.plan.cost) << what;
  EXPECT_EQ(emulated.drive.polyline, native.drive.polyline) << what;
  EXPECT_EQ(emulated.drive.ground_path, native.drive.ground_path) << what;
  EXPECT_TRUE(same_commands(emulated.drive, native.drive)) << what;
}

class WorldSceneCycle : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(WorldSceneCycle, EqualsTheNativeCycleOrStopsOnAMemoryFault) {
  const auto [seed, size] = GetParam();
  world::SceneDescription scene = world::default_scene(static_cast<std::uint64_t>(seed), size);
  const world::RenderedFrame frame = world::render_site(scene);
  const imaging::StereoRig rig(scene.rig);
  nav::NavigationOptions options;
  options.attitude = scene.placement.attitude;
  const nav::NavigationResult native =
      nav::navigate(frame.images.left, frame.images.right, rig, options);
  for (const char* name : {"pc-card", "onboard"}) {
    const emulator::PlatformSpec platform =
        emulator::load_platform(kPlatforms / (std::string(name) + ".toml"));
    const Placement placement = load_program_placement(platform);
    const CycleInput input{frame.images.left, frame.images.right, &rig, options, {}};
    const CycleEmulation run =
        emulate_navigation_cycle(input, CycleSetup{&platform, &placement, std::nullopt, nullptr,
                                                   kOccamStyleFactor, nullptr, std::nullopt});
    const std::string what = std::string(name) + " at " + std::to_string(size);
    const bool must_run = std::string(name) == "pc-card" || size == 128;
    if (run.memory_fault) {
      EXPECT_FALSE(must_run) << what << ": " << describe(*run.memory_fault);
      EXPECT_FALSE(run.result) << what;
      continue;
    }
    ASSERT_TRUE(run.result) << what;
    expect_the_native_result(*run.result, native, what);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds1To20, WorldSceneCycle,
                         ::testing::Combine(::testing::Range(1, 21), ::testing::Values(128, 256)),
                         [](const auto& scene) {
                           return "seed" + std::to_string(std::get<0>(scene.param)) + "_" +
                                  std::to_string(std::get<1>(scene.param));
                         });

} // namespace
} // namespace marsokhod::nav_program
