// CampaignRunner: the scenes and fault-free runs of a campaign, and any run k drawn from the
// campaign's seed and k alone.
#pragma once

#include "campaign_summary.hpp"
#include "fault_verdict.hpp"

#include "marsokhod/emulator/trace/trace_sink.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/occam_port/navigation/placement.hpp"
#include "marsokhod/overswitch/campaign_file.hpp"
#include "marsokhod/world/scene/scene.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// One world seed of the campaign: its scene, ground truth and fault-free run.
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
/// CommandError when that cycle does not finish, or fails a module over.
std::unique_ptr<CampaignScene> supervised_scene(std::uint64_t seed, const SceneChanges& changes,
                                                const emulator::PlatformSpec& platform,
                                                const occam_port::Placement& placement,
                                                const overswitch::Protection& protection);
/// The scene's cycle under `supervisor`, cut at 600 s emulated (a hang).
occam_port::CycleEmulation emulate_supervised(const CampaignScene& scene,
                                              const emulator::PlatformSpec& platform,
                                              const occam_port::Placement& placement,
                                              overswitch::FailoverSupervisor& supervisor,
                                              emulator::TraceSink* trace);
/// The run found a path that crosses a ground-truth obstacle of the scene.
bool crosses_obstacle(const CampaignScene& scene, const occam_port::CycleEmulation& run);

/// What run k is: its scenario and its fault.
struct CampaignDraw {
  std::uint64_t run = 0;
  std::size_t scene = 0;
  overswitch::Fault fault;
};

class CampaignRunner {
public:
  /// Renders every scenario and runs it fault-free on `platform` with the campaign's protection
  /// (and once without, for its cost); `progress` (may be empty) is told each scene done.
  /// CommandError when a fault-free cycle does not finish or a module of the mix is no module of
  /// the overswitch.
  CampaignRunner(const overswitch::CampaignSpec& spec, const emulator::PlatformSpec& platform,
                 const occam_port::Placement& placement,
                 const std::function<void(std::size_t done)>& progress);

  const std::vector<std::unique_ptr<CampaignScene>>& scenes() const { return scenes_; }
  /// The platform as the runs see it: with the protection's costs.
  const emulator::PlatformSpec& platform() const { return platform_; }
  /// Memory bits of the powered modules and the mean fault-free cycles, for the summary.
  CampaignFacts facts() const;
  CampaignDraw draw(std::uint64_t run) const;
  /// Run k's record (one line of runs.jsonl). Without a trace, a run whose fault cannot change
  /// it (an upset the EDAC corrects, or one in memory no block holds at the strike) is not
  /// emulated: its record is made from the fault-free run, as emulating it would give
  /// (docs/faults.md, "Speed"); `skip` false emulates every run. With `trace`, its trace.
  nlohmann::ordered_json run(std::uint64_t run, emulator::TraceSink* trace, bool skip = true) const;
  /// Run k's fault cannot change its run, so run() does not emulate it.
  bool skippable(std::uint64_t run) const;

private:
  /// The fault as it would strike, when it cannot change the run; nothing otherwise.
  std::optional<overswitch::InjectedFault> unchanging(const CampaignDraw& d) const;

  const overswitch::CampaignSpec* spec_;
  emulator::PlatformSpec platform_;
  const occam_port::Placement* placement_;
  std::vector<std::unique_ptr<CampaignScene>> scenes_;
  double total_weight_ = 0.0;
};

} // namespace marsokhod::apps
