// The onboard cycle of world seed 3 under a FailoverSupervisor, the fault-free run, and the
// constants the overswitch tests work their expectations out from.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav_program/placement/memory_plan.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace marsokhod::overswitch {
namespace test {

using emulator::Tick;
using nav_program::CycleEmulation;

inline const std::filesystem::path kPlatforms =
    std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms";

constexpr Tick kMs = emulator::kMillisecond;
constexpr Tick kUs = emulator::kMicrosecond;
/// T805 data book, link protocol: a data byte is 11 bits on the wire (start, 1, 8 data, stop),
/// 1.1 us at 10 Mbit/s; with the acknowledge overlapped a stream runs at that rate.
constexpr Tick kByteOnWire = 1100 * emulator::kNanosecond;
/// A heartbeat byte reaches the overswitch within this of its period's start: the wait for a
/// high-priority process to interrupt low-priority work (T805 data book: at most 78 cycles with
/// the FPU in use, 2.6 us at 30 MHz), its `out`, and the byte on the wire (1.1 us).
constexpr Tick kKickLatency = 4 * kUs;

/// World seed 3 at 128x128, the default site: a scene with rocks and a path through them.
struct Site {
  world::SceneDescription scene = world::default_scene(3, 128);
  world::RenderedFrame frame = world::render_site(scene);
  imaging::StereoRig rig{scene.rig};
};

inline const Site& site() {
  static const Site made;
  return made;
}

class OnboardCycle : public ::testing::Test {
protected:
  OnboardCycle()
      : platform_(emulator::load_platform(kPlatforms / "onboard.toml")),
        placement_(nav_program::load_placement(nav_program::default_placement_file(platform_),
                                               platform_,
                                               nav_program::navigation_program_shape())) {}

  /// The cycle with `faults` and `protection` (on the platform with its costs).
  CycleEmulation emulate(std::vector<Fault> faults, FailoverSupervisor*& out,
                         const Protection& protection = {}) {
    protected_ = protected_platform(platform_, protection);
    supervisor_ = std::make_unique<FailoverSupervisor>(protected_, std::move(faults), protection);
    out = supervisor_.get();
    const Site& s = site();
    nav::NavigationOptions options;
    options.attitude = s.scene.placement.attitude;
    const nav_program::CycleInput input{s.frame.images.left, s.frame.images.right, &s.rig, options,
                                        mission_};
    return nav_program::emulate_navigation_cycle(
        input, nav_program::CycleSetup{&protected_, &placement_, std::nullopt, nullptr,
                                       nav_program::kOccamStyleFactor, supervisor_.get(),
                                       120 * emulator::kSecond});
  }

  /// The fault-free cycle, unprotected, from the mission's start (whatever mission_ says).
  const CycleEmulation& golden() {
    static const CycleEmulation golden = [this] {
      const nav_program::MissionState kept = mission_;
      mission_ = {};
      FailoverSupervisor* unused = nullptr;
      CycleEmulation run = emulate({}, unused);
      mission_ = kept;
      return run;
    }();
    return golden;
  }

  /// The boot stream of module `node`'s share of the program, timed on the wire by hand: its
  /// code bytes and the mission state record (eight INT32 and REAL32 words), one length byte per
  /// block of at most 255.
  Tick boot_time_of(const std::string& node) const {
    const nav_program::MemoryPlan plan =
        nav_program::plan_memory(platform_, placement_, 128, 128, 4, std::nullopt);
    for (const nav_program::NodePlan& node_plan : plan.nodes)
      if (node_plan.node == node) {
        const std::size_t bytes = node_plan.code_bytes + 8 * 4;
        const std::size_t stream = bytes + (bytes + 254) / 255;
        return static_cast<Tick>(stream) * kByteOnWire;
      }
    ADD_FAILURE() << node << " runs none of the program";
    return 0;
  }

  static bool same_path(const CycleEmulation& a, const CycleEmulation& b) {
    return a.result && b.result && a.result->plan.pixels == b.result->plan.pixels &&
           a.result->plan.found == b.result->plan.found;
  }

  emulator::PlatformSpec platform_;
  emulator::PlatformSpec protected_;
  /// The mission state the cycles start from.
  nav_program::MissionState mission_;
  nav_program::Placement placement_;
  std::unique_ptr<FailoverSupervisor> supervisor_;
};

inline Fault fault(Fault::Kind kind, const std::string& module, Tick at,
                   const std::string& stage = "") {
  Fault f;
  f.kind = kind;
  f.module = module;
  f.stage = stage;
  f.offset = at;
  return f;
}

} // namespace test
} // namespace marsokhod::overswitch
