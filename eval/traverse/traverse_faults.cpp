// One fault per course on the emulated computer, judged like a campaign's run.
#include "marsokhod/eval/traverse/traverse_faults.hpp"

#include "marsokhod/eval/campaign/campaign_platform.hpp"
#include "marsokhod/eval/campaign/campaign_scene.hpp"
#include "marsokhod/eval/faults/fault_verdict.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/protection/protection.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"

#include <array>

namespace marsokhod::eval {
namespace {

// The stream the fault's cycle is drawn from, apart from the site's and the slip's.
constexpr std::uint64_t kFaultCycleStream = 0xfa17;

nav_program::CycleEmulation supervised(const nav_program::CycleInput& input,
                                       const emulator::PlatformSpec& platform,
                                       const nav_program::Placement& placement,
                                       overswitch::FailoverSupervisor& supervisor) {
  const nav_program::CycleSetup setup{
      &platform,   &placement,          std::nullopt, nullptr, nav_program::kOccamStyleFactor,
      &supervisor, kSupervisedTimeLimit};
  return nav_program::emulate_navigation_cycle(input, setup);
}

} // namespace

TraverseFaults::TraverseFaults(const std::string& campaign_file, std::uint64_t course_seed)
    : spec_(std::make_unique<const overswitch::CampaignSpec>(
          overswitch::load_campaign(campaign_file))),
      platform_(overswitch::protected_platform(campaign_platform(*spec_), spec_->protection)),
      placement_(nav_program::load_program_placement(platform_)),
      draw_(std::make_unique<FaultDraw>(*spec_, platform_)), course_seed_(course_seed) {
  world::RandomStream rng(world::substream_seed(course_seed, kFaultCycleStream));
  fault_cycle_ = static_cast<int>(rng.uniform() * kFaultCycles);
}

nav_program::CycleEmulation TraverseFaults::run(const nav_program::CycleInput& input, int cycle,
                                                std::optional<TraverseFault>& met) const {
  overswitch::FailoverSupervisor fault_free(platform_, {}, spec_->protection);
  nav_program::CycleEmulation golden = supervised(input, platform_, placement_, fault_free);
  if (cycle != fault_cycle_)
    return golden;
  const std::array<emulator::Tick, 1> golden_cycle{golden.emulated};
  const CampaignDraw drawn = draw_->draw(course_seed_, golden_cycle);
  overswitch::FailoverSupervisor supervisor(platform_, {drawn.fault}, spec_->protection);
  nav_program::CycleEmulation faulted = supervised(input, platform_, placement_, supervisor);
  const FaultVerdict verdict = judge_fault_run(GoldenRun{std::move(golden), false},
                                               supervised_run(faulted, supervisor), false);
  met = TraverseFault{cycle,
                      overswitch::describe(drawn.fault),
                      to_string(verdict.outcome),
                      verdict.path_equals_golden,
                      verdict.delay_s,
                      static_cast<int>(verdict.failovers.size())};
  return faulted;
}

} // namespace marsokhod::eval
