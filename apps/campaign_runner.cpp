// A campaign's scenes, their golden runs, and each run drawn, emulated and judged.

#include "campaign_runner.hpp"

#include "command.hpp"

#include "marsokhod/eval/terrain/terrain_scoring.hpp"
#include "marsokhod/occam_port/navigation/navigation_program.hpp"
#include "marsokhod/overswitch/split_mix.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace marsokhod::apps {
namespace {

namespace emu = emulator;

/// Longest a run may take, emulated: a cycle of about 20 s restarted a few times; past this,
/// with no watchdog running out, the run is a hang.
constexpr emu::Tick kTimeLimit = 600 * emu::kSecond;

std::vector<std::string> powered_modules(const emu::PlatformSpec& platform) {
  std::vector<std::string> names;
  for (const std::string& module : platform.overswitch->modules)
    if (platform.find_node(module)->powered)
      names.push_back(module);
  return names;
}

void draw_link(overswitch::Fault& fault, const overswitch::FaultMix& mix,
               overswitch::SplitMix& random) {
  fault.link = mix.links[random.below(mix.links.size())];
  fault.direction = mix.direction;
  if (mix.down_for_s) {
    const auto [shortest, longest] = *mix.down_for_s;
    fault.duration = static_cast<emu::Tick>((shortest + random.unit() * (longest - shortest)) *
                                            static_cast<double>(emu::kSecond));
  }
  fault.byte = random.below(mix.byte_within);
}

void check_modules(const overswitch::CampaignSpec& spec, const emu::PlatformSpec& platform) {
  const auto& modules = platform.overswitch->modules;
  for (const overswitch::FaultMix& mix : spec.faults)
    for (const std::string& module : mix.modules)
      if (std::find(modules.begin(), modules.end(), module) == modules.end())
        throw overswitch::CampaignError(
            spec.source, mix.line, "modules",
            fmt::format("'{}' is no module of {}'s overswitch", module, platform.name));
}

} // namespace

std::unique_ptr<CampaignScene> supervised_scene(std::uint64_t seed, const SceneChanges& changes,
                                                const emu::PlatformSpec& platform,
                                                const occam_port::Placement& placement,
                                                const overswitch::Protection& protection) {
  auto scene = std::make_unique<CampaignScene>();
  scene->world_seed = seed;
  scene->description = world::default_scene(seed, 128);
  if (changes.light)
    scene->description.lighting = world::lighting_preset(world::parse_light_preset(*changes.light));
  if (changes.rock_cover)
    scene->description.terrain.rock_cover = *changes.rock_cover;
  scene->frame = world::render_site(scene->description);
  scene->rig = std::make_unique<imaging::StereoRig>(scene->description.rig);
  scene->truth_terrain = nav::reconstruct_terrain(scene->frame.truth.disparity, *scene->rig,
                                                  scene->description.placement.attitude);
  overswitch::FailoverSupervisor fault_free(platform, {}, protection);
  fault_free.record_memory(scene->timeline);
  scene->golden.run = emulate_supervised(*scene, platform, placement, fault_free, nullptr);
  if (!scene->golden.run.finished)
    throw CommandError(fmt::format("world seed {}: the fault-free cycle did not finish: {}", seed,
                                   scene->golden.run.abandoned.value_or("no reason given")));
  if (!fault_free.overswitch().failovers().empty() || !scene->golden.run.halts.empty() ||
      !fault_free.troubles().empty())
    throw CommandError(fmt::format(
        "world seed {}: the fault-free cycle failed a module over{}", seed,
        scene->golden.run.halts.empty() ? std::string()
                                        : ": " + scene->golden.run.halts.front().cause));
  scene->golden.unsafe = crosses_obstacle(*scene, scene->golden.run);
  return scene;
}

occam_port::CycleEmulation emulate_supervised(const CampaignScene& scene,
                                              const emu::PlatformSpec& platform,
                                              const occam_port::Placement& placement,
                                              overswitch::FailoverSupervisor& supervisor,
                                              emu::TraceSink* trace) {
  occam_port::CycleInput input{
      scene.frame.images.left, scene.frame.images.right, scene.rig.get(), {}, {}};
  input.options.attitude = scene.description.placement.attitude;
  const occam_port::CycleSetup setup{
      &platform,   &placement, std::nullopt, trace, occam_port::kOccamStyleFactor,
      &supervisor, kTimeLimit};
  return occam_port::emulate_navigation_cycle(input, setup);
}

bool crosses_obstacle(const CampaignScene& scene, const occam_port::CycleEmulation& run) {
  return run.result && run.result->found() &&
         eval::crosses_obstacle(run.result->plan, scene.truth_terrain, scene.frame.truth);
}

CampaignRunner::CampaignRunner(const overswitch::CampaignSpec& spec,
                               const emu::PlatformSpec& platform,
                               const occam_port::Placement& placement,
                               const std::function<void(std::size_t done)>& progress)
    : spec_(&spec), platform_(overswitch::protected_platform(platform, spec.protection)),
      placement_(&placement) {
  check_modules(spec, platform);
  for (const overswitch::FaultMix& mix : spec.faults)
    total_weight_ += mix.weight;
  const SceneChanges changes{spec.light, spec.rock_cover};
  for (const std::uint64_t seed : spec.world_seeds) {
    scenes_.push_back(supervised_scene(seed, changes, platform_, placement, spec.protection));
    CampaignScene& scene = *scenes_.back();
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

// Kind by weight, then module, then the strike time over the fault-free cycle's share.
CampaignDraw CampaignRunner::draw(std::uint64_t run) const {
  overswitch::SplitMix random(spec_->seed, run);
  CampaignDraw d;
  d.run = run;
  d.scene = random.below(scenes_.size());
  double pick = random.unit() * total_weight_;
  const overswitch::FaultMix* mix = &spec_->faults.back();
  for (const overswitch::FaultMix& candidate : spec_->faults) {
    if (pick < candidate.weight) {
      mix = &candidate;
      break;
    }
    pick -= candidate.weight;
  }
  const std::vector<std::string> modules =
      mix->modules.empty() ? powered_modules(platform_) : mix->modules;
  d.fault.kind = mix->kind;
  d.fault.memory = mix->memory;
  d.fault.module = modules[random.below(modules.size())];
  const auto cycle = static_cast<double>(scenes_[d.scene]->golden.run.emulated);
  const double share = mix->from_share + random.unit() * (mix->to_share - mix->from_share);
  d.fault.offset = static_cast<emu::Tick>(share * cycle);
  d.fault.draw = random.next();
  if (overswitch::is_link_fault(mix->kind))
    draw_link(d.fault, *mix, random);
  return d;
}

// Only an upset is left alone by a clean write: a stuck cell forces its value back after it.
std::optional<overswitch::InjectedFault> CampaignRunner::unchanging(const CampaignDraw& d) const {
  if (d.fault.kind != overswitch::Fault::Kind::upset || !d.fault.stage.empty())
    return std::nullopt;
  const bool edac = spec_->protection.edac;
  std::optional<overswitch::MemoryHit> hit =
      overswitch::locate_before_strike(platform_.find_node(d.fault.module)->memory, edac, d.fault);
  if (!hit || hit->reserved)
    return std::nullopt;
  const overswitch::MemoryTimeline::Holding holding =
      scenes_[d.scene]->timeline.holding(d.fault.module, hit->address, d.fault.offset);
  if (!holding.sure)
    return std::nullopt;
  hit->block = holding.block;
  overswitch::InjectedFault fault{d.fault, d.fault.offset, hit, {}};
  if (hit->check_bit || (edac && !hit->on_chip)) {
    fault.hit->effect = emu::UpsetEffect::corrected;
    fault.effect = "EDAC: corrected on every read";
    return fault;
  }
  if (holding.block)
    return std::nullopt;
  fault.effect = "none: free memory";
  return fault;
}

bool CampaignRunner::skippable(std::uint64_t run) const {
  return unchanging(draw(run)).has_value();
}

nlohmann::ordered_json CampaignRunner::run(std::uint64_t run, emu::TraceSink* trace,
                                           bool skip) const {
  const CampaignDraw d = draw(run);
  const CampaignScene& scene = *scenes_[d.scene];
  if (trace == nullptr && skip)
    if (const std::optional<overswitch::InjectedFault> fault = unchanging(d)) {
      nlohmann::ordered_json record;
      record["run"] = run;
      record["world_seed"] = scene.world_seed;
      record["fault"] = injected_json(*fault);
      record.update(verdict_json(
          judge_unchanged_run(scene.golden, fault->hit->effect == emu::UpsetEffect::corrected)));
      return record;
    }
  overswitch::FailoverSupervisor supervisor(platform_, {d.fault}, spec_->protection);
  occam_port::CycleEmulation emulated;
  try {
    emulated = emulate_supervised(scene, platform_, *placement_, supervisor, trace);
  } catch (const std::exception& error) {
    // The model's own failure, not the fault's outcome: name what reproduces it.
    throw std::runtime_error(fmt::format("run {} (world seed {}, {}): {}", run, scene.world_seed,
                                         overswitch::describe(d.fault), error.what()));
  }
  const FaultVerdict verdict =
      judge_fault_run(scene.golden, emulated, supervisor, crosses_obstacle(scene, emulated));
  nlohmann::ordered_json record;
  record["run"] = run;
  record["world_seed"] = scene.world_seed;
  record["fault"] = supervisor.injected().empty()
                        ? nlohmann::ordered_json{{"kind", overswitch::to_string(d.fault.kind)},
                                                 {"module", d.fault.module},
                                                 {"at_s", emu::to_seconds(d.fault.offset)},
                                                 {"spec", overswitch::describe(d.fault)}}
                        : injected_json(supervisor.injected().front());
  record.update(verdict_json(verdict));
  return record;
}

} // namespace marsokhod::apps
