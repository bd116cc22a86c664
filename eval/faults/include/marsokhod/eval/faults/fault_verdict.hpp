// The verdict on one fault run: its outcome class against the fault-free golden run and the
// world's ground truth (docs/faults.md, "Outcome classes").
#pragma once

#include "marsokhod/eval/faults/outcome.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// What a run is judged against: the fault-free run on the same platform and scene, and
/// whether its path crosses a ground-truth obstacle (the navigation's own error, never blamed
/// on a fault).
struct GoldenRun {
  nav_program::CycleEmulation run;
  bool unsafe = false;
};

/// What the verdict reads of a supervised run: the cycle as it ended and what the overswitch
/// saw and did. Views: the run and its supervisor outlive it.
struct SupervisedRun {
  const nav_program::CycleEmulation* cycle = nullptr;
  std::span<const overswitch::Failover> failovers;
  std::span<const overswitch::InjectedFault> injected;
  std::span<const overswitch::ReportedTrouble> troubles;
  /// An injected fault named nothing the run has (FailoverSupervisor::error).
  std::optional<std::string> error;
};

/// The supervised run of `cycle` under `supervisor`.
SupervisedRun supervised_run(const nav_program::CycleEmulation& cycle,
                             const overswitch::FailoverSupervisor& supervisor);

/// One failover as reported: the module, its spare (empty if none) and the boot's time.
struct FailoverFigure {
  std::string failed;
  std::string spare;
  double boot_s = 0.0; ///< from the spare's power-on to it running; 0 when it never ran
  friend bool operator==(const FailoverFigure&, const FailoverFigure&) = default;
};

/// A module halted on an error (HaltOnError): where, why and when.
struct HaltFigure {
  std::string module;
  std::string process;
  std::string what;
  std::string cause;
  double time_s = 0.0;
  friend bool operator==(const HaltFigure&, const HaltFigure&) = default;
};

/// A link trouble a module reported: which link, to which module, what, and when.
struct LinkTroubleFigure {
  std::string module;
  int link = 0;
  std::string peer;
  std::string trouble;
  double time_s = 0.0;
  friend bool operator==(const LinkTroubleFigure&, const LinkTroubleFigure&) = default;
};

/// The outcome of a fault run and the figures it was judged by.
struct FaultVerdict {
  Outcome outcome = Outcome::error;
  std::string reason; ///< why an error, a hang or a safe stop; empty otherwise
  /// The fault reached the program: it stopped a module, a module reported a link trouble, or
  /// a memory fault reached data or control state uncorrected.
  bool activated = false;
  bool detected = false;
  /// From the first fault to the first watchdog expiry or link trouble reported.
  std::optional<double> detection_latency_s;
  std::optional<double> recovery_s; ///< from the first expiry to the pair being whole again
  std::vector<FailoverFigure> failovers;
  std::vector<HaltFigure> halts;
  int restarts = 0; ///< times the cycle was started again (after a failover or a link trouble)
  std::vector<LinkTroubleFigure> link_troubles;
  bool path_equals_golden = false;
  bool unsafe = false;
  bool golden_unsafe = false;
  bool telemetry_lost = false;
  bool wheels_commanded_while_failed = false;
  double emulated_s = 0.0;
  double delay_s = 0.0; ///< the cycle's end after the golden one's
  friend bool operator==(const FaultVerdict&, const FaultVerdict&) = default;
};

/// Judges a run that ended (finished, abandoned, cut by its time limit, or faulted).
/// `crosses_obstacle` says whether a finished run's path crosses a ground-truth obstacle.
FaultVerdict judge_fault_run(const GoldenRun& golden, const SupervisedRun& run,
                             bool crosses_obstacle);

/// The verdict on a run its fault cannot have changed (an upset the EDAC corrects, one in memory
/// no block holds): the fault-free run's, masked, and seen by the EDAC when it corrected it.
FaultVerdict judge_unchanged_run(const GoldenRun& golden, bool edac_corrected);

/// The verdict's keys of a run record, in the order records give them (docs/faults.md lists
/// them): `outcome`, `reason` (when there is one), `activated`, `detected`, ...
void to_json(nlohmann::ordered_json& json, const FaultVerdict& verdict);
/// The verdict back from a record; RecordError naming the key when one is missing or wrong.
void from_json(const nlohmann::json& json, FaultVerdict& verdict);

} // namespace marsokhod::eval
