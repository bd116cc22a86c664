// FailoverSupervisor: the overswitch, the heartbeats and the injected faults around a cycle.
#pragma once

#include "marsokhod/nav_program/run/cycle_supervisor.hpp"
#include "marsokhod/overswitch/faults/fault.hpp"
#include "marsokhod/overswitch/faults/memory_strike.hpp"
#include "marsokhod/overswitch/faults/memory_timeline.hpp"
#include "marsokhod/overswitch/protection/protection.hpp"
#include "marsokhod/overswitch/supervision/overswitch.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::overswitch {

/// A fault as it happened in the run.
struct InjectedFault {
  Fault fault;
  emulator::Tick at = 0;
  /// A memory fault: the bit it struck and what that did.
  std::optional<MemoryHit> hit;
  /// What the fault did at once ("module hung: its code was struck", "EDAC corrected it"...).
  std::string effect;
};

/// A link trouble a module reported to the overswitch.
struct ReportedTrouble {
  emulator::Tick at = 0;
  std::string module;
  int link = 0;
  std::string peer; ///< the module at the link's other end
  nav_program::LinkTrouble trouble = nav_program::LinkTrouble::timeout;
};

/// Supervises one emulated cycle on a platform with an [overswitch] table: starts a heartbeat
/// on each powered module, arms the overswitch's watchdogs, injects the faults when they are
/// due, and on each failover boots the spare over a link from the survivor and restarts the
/// cycle with the failed module's processes on the spare; a safe stop abandons the cycle.
class FailoverSupervisor final : public nav_program::CycleSupervisor {
public:
  /// std::invalid_argument when the platform has no [overswitch] table. The platform must
  /// already carry the protection's costs (protected_platform).
  FailoverSupervisor(const emulator::PlatformSpec& platform, std::vector<Fault> faults,
                     Protection protection = {});
  FailoverSupervisor(const FailoverSupervisor&) = delete;
  FailoverSupervisor& operator=(const FailoverSupervisor&) = delete;
  ~FailoverSupervisor() override;

  /// Records the modules' blocks over the run into `timeline` (call before the run).
  void record_memory(MemoryTimeline& timeline) { timeline_ = &timeline; }

  void attach(nav_program::CycleControl& control) override;
  /// The platform's link timeout, and checksums when the protection has them.
  nav_program::LinkGuard link_guard() const override;
  bool check_terrain() const override { return protection_.terrain_check; }
  void stage_started(const std::string& process, emulator::Tick at) override;
  /// Winds the heartbeats and watchdogs down: at once, or, when a fault has struck that no
  /// watchdog has seen yet, after long enough for one to (a period for the last kick, the
  /// timeout) and for a spare to boot, so that a late fault is still seen and handled.
  void program_finished() override;
  void detach() override;

  /// After the run: the overswitch's log and failovers, and the faults that happened.
  const Overswitch& overswitch() const { return *overswitch_; }
  const std::vector<InjectedFault>& injected() const { return injected_; }
  /// The link troubles the modules reported, in order.
  const std::vector<ReportedTrouble>& troubles() const { return troubles_; }
  /// An injected fault that named no node of the platform or no stage of the program.
  const std::optional<std::string>& error() const { return error_; }

private:
  void schedule(const Fault& fault, emulator::Tick at);
  void inject(const Fault& fault);
  void leak(emulator::Node& node, const Fault& fault);
  void strike(emulator::Node& node, InjectedFault& injected);
  void protect(emulator::Node& module);
  void strike_link(emulator::Node& node, InjectedFault& injected);
  void link_trouble(const std::string& module, int link, nav_program::LinkTrouble trouble);
  void boot(emulator::Node& spare, emulator::Node& from, std::function<void()> done);
  void booted(const Failover& failover);
  void wind_down();

  const emulator::PlatformSpec* platform_;
  std::vector<Fault> faults_;
  Protection protection_;
  std::vector<bool> scheduled_;
  nav_program::CycleControl* control_ = nullptr;
  std::unique_ptr<Overswitch> overswitch_;
  /// Modules that ran a share of the program and failed, oldest first, until a spare takes
  /// their place.
  std::vector<std::string> vacated_;
  std::vector<InjectedFault> injected_;
  std::optional<std::string> error_;
  MemoryTimeline* timeline_ = nullptr;
  std::vector<ReportedTrouble> troubles_;
  /// Troubles reported on each wire ("module0-module1"): the first restarts the cycle on the
  /// same pair, the next fails the module at the far end.
  std::map<std::string, int> wire_troubles_;
  /// Tells the heartbeats to end at their next beat.
  bool heartbeats_stop_ = false;
};

} // namespace marsokhod::overswitch
