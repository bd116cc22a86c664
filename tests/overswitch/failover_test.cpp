// The overswitch on the onboard computer: a hang or a power loss is found by its watchdog at
// the time the platform's constants give, a spare boots over a link in the time its code takes
// on the wire, and the restarted cycle plans the fault-free path; with nothing left to form a
// pair, a safe stop.

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/occam_port/navigation/memory_plan.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"
#include "marsokhod/overswitch/failover_supervisor.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace marsokhod::overswitch {
namespace {

using emulator::Tick;
using occam_port::CycleEmulation;

const std::filesystem::path kPlatforms = std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms";

constexpr Tick kMs = emulator::kMillisecond;
constexpr Tick kUs = emulator::kMicrosecond;
/// T805 data book, link protocol: a data byte is 11 bits on the wire (start, 1, 8 data, stop),
/// 1.1 us at 10 Mbit/s; with the acknowledge overlapped a stream runs at that rate.
constexpr Tick kByteOnWire = 1100 * emulator::kNanosecond;
/// A heartbeat byte reaches the overswitch within this of its period's start: the wait for a
/// high-priority process to interrupt low-priority work (T805 data book: at most 78 cycles with
/// the FPU in use, 2.6 us at 30 MHz), its `out`, and the byte on the wire (1.1 us).
constexpr Tick kKickLatency = 4 * kUs;

/// World seed 2 at 128x128, the default site: a scene with rocks and a path through them.
struct Site {
  world::SceneDescription scene = world::default_scene(2, 128);
  world::RenderedFrame frame = world::render_site(scene);
  imaging::StereoRig rig{scene.rig};
};

const Site& site() {
  static const Site made;
  return made;
}

class FailoverTest : public ::testing::Test {
protected:
  FailoverTest()
      : platform_(emulator::load_platform(kPlatforms / "onboard.toml")),
        placement_(occam_port::load_placement(occam_port::default_placement_file(platform_),
                                              platform_, occam_port::navigation_program_shape())) {}

  CycleEmulation emulate(std::vector<Fault> faults, FailoverSupervisor*& out) {
    supervisor_ = std::make_unique<FailoverSupervisor>(platform_, std::move(faults));
    out = supervisor_.get();
    const Site& s = site();
    nav::NavigationOptions options;
    options.attitude = s.scene.placement.attitude;
    const occam_port::CycleInput input{s.frame.images.left, s.frame.images.right, &s.rig, options};
    return occam_port::emulate_navigation_cycle(
        input, occam_port::CycleSetup{&platform_, &placement_, std::nullopt, nullptr,
                                      occam_port::kOccamStyleFactor, supervisor_.get(),
                                      120 * emulator::kSecond});
  }

  const CycleEmulation& golden() {
    static const CycleEmulation golden = [this] {
      FailoverSupervisor* unused = nullptr;
      return emulate({}, unused);
    }();
    return golden;
  }

  /// The boot stream of module `node`'s share of the program, timed on the wire by hand: its
  /// code bytes, one length byte per block of at most 255.
  Tick boot_time_of(const std::string& node) const {
    const occam_port::MemoryPlan plan =
        occam_port::plan_memory(platform_, placement_, 128, 128, 4, std::nullopt);
    for (const occam_port::NodePlan& node_plan : plan.nodes)
      if (node_plan.node == node) {
        const std::size_t stream = node_plan.code_bytes + (node_plan.code_bytes + 254) / 255;
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
  occam_port::Placement placement_;
  std::unique_ptr<FailoverSupervisor> supervisor_;
};

Fault fault(Fault::Kind kind, const std::string& module, Tick at, const std::string& stage = "") {
  Fault f;
  f.kind = kind;
  f.module = module;
  f.stage = stage;
  f.offset = at;
  return f;
}

TEST_F(FailoverTest, FaultFreeRunFinishesWithoutAnOverswitchEvent) {
  const CycleEmulation& run = golden();
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 0);
  ASSERT_TRUE(run.result);
  EXPECT_TRUE(run.result->plan.found);
  EXPECT_FALSE(run.abandoned);
}

TEST_F(FailoverTest, HangIsFoundOneTimeoutAfterTheLastKickAndTheSpareBootsInItsStreamTime) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs)}, supervisor);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  // Kicks every 100 ms from t = 0: the last before the hang is at 1.0 s; 200 ms later the
  // watchdog runs out.
  EXPECT_GE(failover.detected, 1200 * kMs);
  EXPECT_LE(failover.detected, 1200 * kMs + kKickLatency);
  EXPECT_EQ(failover.failed, "module1");
  EXPECT_EQ(failover.spare, "module2");
  EXPECT_EQ(failover.booted_from, "module0");
  ASSERT_TRUE(failover.ok);
  const Tick boot = failover.booted - failover.detected;
  const Tick expected = boot_time_of("module1");
  EXPECT_GE(boot, expected);
  EXPECT_LE(boot, expected + expected / 100) << "boot " << boot << " ps, stream " << expected;
  ASSERT_TRUE(run.finished);
  EXPECT_EQ(run.restarts, 1);
  EXPECT_TRUE(same_path(run, golden()));
  for (const occam_port::DeviceUpload& upload : run.uploads)
    EXPECT_NE(upload.node, "module1") << "an upload from the hung module";
}

TEST_F(FailoverTest, PowerLossAtANamedStageMovesThatModulesShareToTheSpare) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run =
      emulate({fault(Fault::Kind::power_loss, "module0", 500 * kMs, "matching")}, supervisor);
  ASSERT_EQ(supervisor->injected().size(), 1U);
  const Tick lost = supervisor->injected()[0].at;
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  // The watchdog runs out 200 ms after the last kick at or before the loss.
  const Tick last_kick = lost / (100 * kMs) * (100 * kMs);
  EXPECT_GE(failover.detected, last_kick + 200 * kMs);
  EXPECT_LE(failover.detected, last_kick + 200 * kMs + kKickLatency);
  EXPECT_EQ(failover.spare, "module2");
  EXPECT_EQ(failover.booted_from, "module1");
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
  const auto& processes = run.processes;
  const auto acquire = std::find_if(processes.begin(), processes.end(),
                                    [](const auto& p) { return p.name == "acquire"; });
  ASSERT_NE(acquire, processes.end());
  EXPECT_EQ(acquire->node, "module2");
}

TEST_F(FailoverTest, WithEverySpareUsedTheOverswitchStopsSafely) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1000 * kMs),
                                      fault(Fault::Kind::hang, "module2", 2000 * kMs),
                                      fault(Fault::Kind::hang, "module3", 3000 * kMs)},
                                     supervisor);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 3U);
  EXPECT_EQ(failovers[1].spare, "module3");
  EXPECT_TRUE(failovers[2].spare.empty());
  // module3 kicks every 100 ms from its boot: its last kick before 3 s, then the timeout.
  const Tick booted = failovers[1].booted;
  const Tick last_kick = booted + (3000 * kMs - booted) / (100 * kMs) * (100 * kMs);
  EXPECT_GE(failovers[2].detected, last_kick + 200 * kMs);
  EXPECT_LE(failovers[2].detected, last_kick + 200 * kMs + kKickLatency);
  EXPECT_TRUE(supervisor->overswitch().safe_stopped());
  EXPECT_FALSE(run.finished);
  ASSERT_TRUE(run.abandoned);
  EXPECT_EQ(run.emulated, failovers[2].detected);
}

TEST_F(FailoverTest, PartnerFailingDuringTheBootLeavesNothingToBootFrom) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs),
                                      fault(Fault::Kind::hang, "module0", 1205 * kMs)},
                                     supervisor);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 2U);
  EXPECT_FALSE(failovers[0].ok); // module0 died while sending module2 its code
  EXPECT_EQ(failovers[1].failed, "module0");
  // module0's last kick was at 1.2 s.
  EXPECT_GE(failovers[1].detected, 1400 * kMs);
  EXPECT_LE(failovers[1].detected, 1400 * kMs + kKickLatency);
  EXPECT_TRUE(supervisor->overswitch().safe_stopped());
  EXPECT_FALSE(run.finished);
}

TEST_F(FailoverTest, SpareThatDoesNotBootIsFailedAfterItsAllowanceAndTheNextOneTaken) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run = emulate({fault(Fault::Kind::hang, "module1", 1050 * kMs),
                                      fault(Fault::Kind::hang, "module2", 1201 * kMs)},
                                     supervisor);
  const auto& failovers = supervisor->overswitch().failovers();
  ASSERT_EQ(failovers.size(), 2U);
  EXPECT_EQ(failovers[1].failed, "module2");
  EXPECT_EQ(failovers[1].spare, "module3");
  // The allowance (1 s) runs from module2's power-on, when module1 was found failed.
  EXPECT_EQ(failovers[1].detected, failovers[0].detected + 1000 * kMs);
  ASSERT_TRUE(failovers[1].ok);
  ASSERT_TRUE(run.finished);
  EXPECT_TRUE(same_path(run, golden()));
}

TEST_F(FailoverTest, LeakHaltsTheModuleAtItsNextBufferAndItsWatchdogFailsItOver) {
  FailoverSupervisor* supervisor = nullptr;
  const CycleEmulation run =
      emulate({fault(Fault::Kind::leak, "module1", 100 * kMs, "zones")}, supervisor);
  // The leak takes module1's free memory; the next buffer there fails and the module halts
  // (HaltOnError); its heartbeat stops with it.
  ASSERT_EQ(run.halts.size(), 1U);
  EXPECT_EQ(run.halts[0].node, "module1");
  EXPECT_GE(run.halts[0].time, supervisor->injected().at(0).at);
  ASSERT_EQ(supervisor->overswitch().failovers().size(), 1U);
  const Failover& failover = supervisor->overswitch().failovers()[0];
  const Tick halted = run.halts[0].time;
  const Tick last_kick = halted / (100 * kMs) * (100 * kMs);
  EXPECT_GE(failover.detected, last_kick + 200 * kMs);
  EXPECT_LE(failover.detected, last_kick + 200 * kMs + kKickLatency);
  EXPECT_EQ(failover.spare, "module2");
  ASSERT_TRUE(run.finished);
  EXPECT_FALSE(run.memory_fault);
  EXPECT_TRUE(same_path(run, golden()));
}

} // namespace
} // namespace marsokhod::overswitch
