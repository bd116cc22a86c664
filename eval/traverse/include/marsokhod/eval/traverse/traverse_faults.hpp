// The emulated computer's faults during a traverse: a campaign file's fault mix, one fault per
// course, struck in one cycle, the overswitch failing over, the time it cost.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/campaign/fault_draw.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace marsokhod::eval {

/// A fault as the traverse met it: where, what, and what the overswitch made of it.
struct TraverseFault {
  int cycle = 0;
  std::string fault;        ///< overswitch::describe of the drawn fault
  std::string outcome;      ///< the fault run's outcome class (docs/faults.md)
  bool recovered = false;   ///< the cycle gave the fault-free cycle's path
  double time_lost_s = 0.0; ///< the cycle's end after the fault-free one's
  int failovers = 0;
};

/// The faults of a course's emulated computer: the campaign file's platform (with its
/// protection's costs), fault mix and protection. The course's fault strikes in one of its
/// first kFaultCycles cycles, drawn from the course's seed, at a time the mix draws over that
/// cycle's fault-free emulated time; a course that ends before that cycle meets no fault.
class TraverseFaults {
public:
  /// Loads the campaign file: overswitch::CampaignError (its file, line and key) when it is
  /// wrong, emulator::PlatformError or overswitch::NoOverswitchError for its platform.
  TraverseFaults(const std::string& campaign_file, std::uint64_t course_seed);

  const emulator::PlatformSpec& platform() const { return platform_; }
  const nav_program::Placement& placement() const { return placement_; }
  int fault_cycle() const { return fault_cycle_; }
  /// The platform as the campaign file names it (a shipped platform's name, or a file).
  const std::string& platform_name() const { return spec_->platform; }

  /// The cycle of `input` run supervised by the overswitch, with the course's fault when
  /// `cycle` is its cycle (then `met` receives what happened).
  nav_program::CycleEmulation run(const nav_program::CycleInput& input, int cycle,
                                  std::optional<TraverseFault>& met) const;

private:
  std::unique_ptr<const overswitch::CampaignSpec> spec_; ///< FaultDraw points at it
  emulator::PlatformSpec platform_;
  nav_program::Placement placement_;
  std::unique_ptr<FaultDraw> draw_;
  std::uint64_t course_seed_ = 0;
  int fault_cycle_ = 0;
};

/// The cycles a course's fault is drawn over: the 8-9 cycles a rock-free 80 m course takes
/// (docs/traverse.md), so that most courses meet theirs.
inline constexpr int kFaultCycles = 8;

} // namespace marsokhod::eval
