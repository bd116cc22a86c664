// A fault study's scene: rendered, its ground truth's terrain, its fault-free supervised run.

#include "marsokhod/eval/campaign/campaign_scene.hpp"

#include "marsokhod/eval/campaign/campaign_error.hpp"
#include "marsokhod/eval/terrain/terrain_scoring.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <fmt/format.h>

namespace marsokhod::eval {
namespace {

world::SceneDescription changed_scene(std::uint64_t seed, const SceneChanges& changes) {
  world::SceneDescription scene = world::default_scene(seed, 128);
  if (changes.light)
    scene.lighting = world::lighting_preset(world::parse_light_preset(*changes.light));
  if (changes.rock_cover)
    scene.terrain.rock_cover = *changes.rock_cover;
  return scene;
}

void check_fault_free(const CampaignScene& scene, const overswitch::FailoverSupervisor& run) {
  const nav_program::CycleEmulation& golden = scene.golden.run;
  if (!golden.finished)
    throw CampaignRunError(fmt::format("world seed {}: the fault-free cycle did not finish: {}",
                                       scene.world_seed,
                                       golden.abandoned.value_or("no reason given")));
  if (run.overswitch().failovers().empty() && golden.halts.empty() && run.troubles().empty())
    return;
  throw CampaignRunError(
      fmt::format("world seed {}: the fault-free cycle failed a module over{}", scene.world_seed,
                  golden.halts.empty() ? std::string() : ": " + golden.halts.front().cause));
}

} // namespace

std::unique_ptr<CampaignScene> supervised_scene(std::uint64_t seed, const SceneChanges& changes,
                                                const emulator::PlatformSpec& platform,
                                                const nav_program::Placement& placement,
                                                const overswitch::Protection& protection) {
  auto scene = std::make_unique<CampaignScene>();
  scene->world_seed = seed;
  scene->description = changed_scene(seed, changes);
  scene->frame = world::render_site(scene->description);
  scene->rig = std::make_unique<imaging::StereoRig>(scene->description.rig);
  scene->truth_terrain = nav::reconstruct_terrain(scene->frame.truth.disparity, *scene->rig,
                                                  scene->description.placement.attitude);
  overswitch::FailoverSupervisor fault_free(platform, {}, protection);
  fault_free.record_memory(scene->timeline);
  scene->golden.run = emulate_supervised(*scene, platform, placement, fault_free, nullptr);
  check_fault_free(*scene, fault_free);
  scene->golden.unsafe = crosses_obstacle(*scene, scene->golden.run);
  return scene;
}

nav_program::CycleEmulation emulate_supervised(const CampaignScene& scene,
                                               const emulator::PlatformSpec& platform,
                                               const nav_program::Placement& placement,
                                               overswitch::FailoverSupervisor& supervisor,
                                               emulator::TraceSink* trace) {
  nav_program::CycleInput input{
      scene.frame.images.left, scene.frame.images.right, scene.rig.get(), {}, {}};
  input.options.attitude = scene.description.placement.attitude;
  const nav_program::CycleSetup setup{
      &platform,   &placement,          std::nullopt, trace, nav_program::kOccamStyleFactor,
      &supervisor, kSupervisedTimeLimit};
  return nav_program::emulate_navigation_cycle(input, setup);
}

bool crosses_obstacle(const CampaignScene& scene, const nav_program::CycleEmulation& run) {
  return run.result && run.result->found() &&
         crosses_obstacle(run.result->plan, scene.truth_terrain, scene.frame.truth);
}

FaultVerdict judge_scene_run(const CampaignScene& scene, const nav_program::CycleEmulation& run,
                             const overswitch::FailoverSupervisor& supervisor) {
  return judge_fault_run(scene.golden, supervised_run(run, supervisor),
                         crosses_obstacle(scene, run));
}

} // namespace marsokhod::eval
