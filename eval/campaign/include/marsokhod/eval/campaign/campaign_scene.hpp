// CampaignScene: one world seed of a fault study, rendered with its ground truth, and its
// fault-free run under the overswitch.
#pragma once

#include "marsokhod/emulator/trace/trace_sink.hpp"
#include "marsokhod/eval/faults/fault_verdict.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"
#include "marsokhod/overswitch/faults/memory_timeline.hpp"
#include "marsokhod/overswitch/protection/protection.hpp"
#include "marsokhod/world/scene/scene.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::eval {

/// Longest a supervised run may take, emulated: a cycle of about 20 s restarted a few times;
/// past this, with no watchdog running out, the run is a hang.
inline constexpr emulator::Tick kSupervisedTimeLimit = 600 * emulator::kSecond;

/// One world seed of a fault study: its scene, ground truth and fault-free run.
struct CampaignScene {
  std::uint64_t world_seed = 0;
  world::SceneDescription description;
  world::RenderedFrame frame;
  std::unique_ptr<imaging::StereoRig> rig;
  nav::TerrainPoints truth_terrain;
  GoldenRun golden;
  /// The blocks the modules held over the fault-free run.
  overswitch::MemoryTimeline timeline;
  /// The fault-free cycle without the campaign's protection (its cost); the golden one's when
  /// nothing is switched on.
  emulator::Tick unprotected_cycle = 0;
};

/// What a campaign changes in the default site; nothing when empty.
struct SceneChanges {
  std::optional<std::string> light; ///< a light preset's name
  std::optional<double> rock_cover;
};

/// World `seed` at 128x128, rendered with its ground truth, and its fault-free cycle under the
/// overswitch with `protection` (on a platform that carries its costs: protected_platform);
/// CampaignRunError when that cycle does not finish, or fails a module over.
std::unique_ptr<CampaignScene> supervised_scene(std::uint64_t seed, const SceneChanges& changes,
                                                const emulator::PlatformSpec& platform,
                                                const nav_program::Placement& placement,
                                                const overswitch::Protection& protection);

/// The scene's cycle under `supervisor`, cut at kSupervisedTimeLimit (a hang).
nav_program::CycleEmulation emulate_supervised(const CampaignScene& scene,
                                               const emulator::PlatformSpec& platform,
                                               const nav_program::Placement& placement,
                                               overswitch::FailoverSupervisor& supervisor,
                                               emulator::TraceSink* trace);

/// The run found a path that crosses a ground-truth obstacle of the scene.
bool crosses_obstacle(const CampaignScene& scene, const nav_program::CycleEmulation& run);

/// The run under `supervisor` judged against the scene's golden run and ground truth.
FaultVerdict judge_scene_run(const CampaignScene& scene, const nav_program::CycleEmulation& run,
                             const overswitch::FailoverSupervisor& supervisor);

} // namespace marsokhod::eval
