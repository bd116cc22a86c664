// A campaign's scenes, their golden runs, and each run drawn, emulated and judged.

#include "marsokhod/eval/campaign/campaign_runner.hpp"

#include "marsokhod/eval/campaign/campaign_error.hpp"
#include "marsokhod/eval/campaign/skip_prediction.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <fmt/format.h>

namespace marsokhod::eval {

namespace emu = emulator;

CampaignRunner::CampaignRunner(const overswitch::CampaignSpec& spec,
                               const emu::PlatformSpec& platform,
                               const nav_program::Placement& placement,
                               const std::function<void(std::size_t done)>& progress)
    : spec_(&spec), platform_(overswitch::protected_platform(platform, spec.protection)),
      placement_(&placement), fault_draw_(spec, platform_) {
  const SceneChanges changes{spec.light, spec.rock_cover};
  for (const std::uint64_t seed : spec.world_seeds) {
    scenes_.push_back(supervised_scene(seed, changes, platform_, placement, spec.protection));
    CampaignScene& scene = *scenes_.back();
    golden_cycles_.push_back(scene.golden.run.emulated);
    scene.unprotected_cycle = scene.golden.run.emulated;
    if (overswitch::any(spec.protection)) {
      overswitch::FailoverSupervisor bare(platform, {});
      scene.unprotected_cycle =
          emulate_supervised(scene, platform, placement, bare, nullptr).emulated;
    }
    if (progress)
      progress(scenes_.size());
  }
}

// The bits an upset may strike: all the memory of the modules powered at the start, and the
// EDAC's 7 check bits per word of external memory.
CampaignFacts CampaignRunner::facts() const {
  CampaignFacts f;
  for (const std::string& module : powered_modules(platform_)) {
    const emu::MemoryConfig& memory = platform_.find_node(module)->memory;
    f.memory_bits += 8 * (memory.on_chip_bytes + memory.external_bytes);
    if (spec_->protection.edac)
      f.memory_bits += memory.external_bytes / emu::MemoryArena::kWordBytes * emu::kEdacCheckBits;
  }
  for (const auto& scene : scenes_) {
    f.cycle_s += emu::to_seconds(scene->golden.run.emulated);
    f.unprotected_cycle_s += emu::to_seconds(scene->unprotected_cycle);
  }
  f.cycle_s /= static_cast<double>(scenes_.size());
  f.unprotected_cycle_s /= static_cast<double>(scenes_.size());
  return f;
}

CampaignDraw CampaignRunner::draw(std::uint64_t run) const {
  return fault_draw_.draw(run, golden_cycles_);
}

bool CampaignRunner::skippable(std::uint64_t run) const {
  const CampaignDraw d = draw(run);
  return unchanging_fault(d, *scenes_[d.scene], platform_, spec_->protection.edac).has_value();
}

RunRecord CampaignRunner::run(std::uint64_t run, emu::TraceSink* trace, bool skip) const {
  const CampaignDraw d = draw(run);
  const CampaignScene& scene = *scenes_[d.scene];
  if (trace == nullptr && skip)
    if (const std::optional<overswitch::InjectedFault> fault =
            unchanging_fault(d, scene, platform_, spec_->protection.edac))
      return {run, scene.world_seed, fault_record(*fault),
              judge_unchanged_run(scene.golden, fault->hit->effect == emu::UpsetEffect::corrected)};
  overswitch::FailoverSupervisor supervisor(platform_, {d.fault}, spec_->protection);
  nav_program::CycleEmulation emulated;
  try {
    emulated = emulate_supervised(scene, platform_, *placement_, supervisor, trace);
  } catch (const std::exception& error) {
    // The model's own failure, not the fault's outcome: name what reproduces it.
    throw CampaignRunError(fmt::format("run {} (world seed {}, {}): {}", run, scene.world_seed,
                                       overswitch::describe(d.fault), error.what()));
  }
  return {run, scene.world_seed,
          supervisor.injected().empty() ? drawn_fault_record(d.fault)
                                        : fault_record(supervisor.injected().front()),
          judge_scene_run(scene, emulated, supervisor)};
}

} // namespace marsokhod::eval
