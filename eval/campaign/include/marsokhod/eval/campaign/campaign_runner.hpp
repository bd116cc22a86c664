// CampaignRunner: the scenes and fault-free runs of a campaign, and any run k drawn from the
// campaign's seed and k alone, emulated and judged.
#pragma once

#include "marsokhod/emulator/trace/trace_sink.hpp"
#include "marsokhod/eval/campaign/campaign_scene.hpp"
#include "marsokhod/eval/campaign/fault_draw.hpp"
#include "marsokhod/eval/faults/fault_record.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace marsokhod::eval {

/// What a campaign's summary needs of it besides its records.
struct CampaignFacts {
  /// Bits an upset may strike in the powered modules: their memory, and the EDAC's check bits.
  std::uint64_t memory_bits = 0;
  /// Mean fault-free cycle over the scenes, with the campaign's protection and without it.
  double cycle_s = 0.0;
  double unprotected_cycle_s = 0.0;
  /// Runs judged from the fault-free run without being emulated (CampaignRunner::skippable).
  std::uint64_t skipped_runs = 0;
};

/// Runs a campaign's runs one at a time, each from the campaign's seed and its number alone.
class CampaignRunner {
public:
  /// Renders every scenario and runs it fault-free on `platform` with the campaign's protection
  /// (and once without, for its cost); `progress` (may be empty) is told each scene done.
  /// CampaignRunError when a fault-free cycle does not finish; overswitch::CampaignError when a
  /// module of the mix is no module of the overswitch.
  CampaignRunner(const overswitch::CampaignSpec& spec, const emulator::PlatformSpec& platform,
                 const nav_program::Placement& placement,
                 const std::function<void(std::size_t done)>& progress);

  const std::vector<std::unique_ptr<CampaignScene>>& scenes() const { return scenes_; }
  /// The platform as the runs see it: with the protection's costs.
  const emulator::PlatformSpec& platform() const { return platform_; }
  /// Memory bits of the powered modules and the mean fault-free cycles, for the summary.
  CampaignFacts facts() const;
  CampaignDraw draw(std::uint64_t run) const;
  /// Run k's record. Without a trace, a run whose fault cannot change it (unchanging_fault) is
  /// not emulated: its record is made from the fault-free run, as emulating it would give;
  /// `skip` false emulates every run. With `trace`, its trace. CampaignRunError naming the run,
  /// its world seed and fault when the model fails on it.
  RunRecord run(std::uint64_t run, emulator::TraceSink* trace, bool skip = true) const;
  /// Run k's fault cannot change its run, so run() does not emulate it.
  bool skippable(std::uint64_t run) const;

private:
  const overswitch::CampaignSpec* spec_;
  emulator::PlatformSpec platform_;
  const nav_program::Placement* placement_;
  FaultDraw fault_draw_;
  std::vector<std::unique_ptr<CampaignScene>> scenes_;
  std::vector<emulator::Tick> golden_cycles_;
};

} // namespace marsokhod::eval
