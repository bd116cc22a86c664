// The verdict on one fault run: its outcome class against the fault-free golden run and the
// world's ground truth (docs/faults.md, "Outcome classes").
#pragma once

#include "marsokhod/occam_port/navigation/navigation_program.hpp"
#include "marsokhod/overswitch/failover_supervisor.hpp"
#include "marsokhod/world/render/renderer.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {

/// What a run is judged against: the fault-free run on the same platform and scene, and
/// whether its path crosses a ground-truth obstacle (the navigation's own error, never blamed
/// on a fault).
struct GoldenRun {
  occam_port::CycleEmulation run;
  bool unsafe = false;
};

/// The classes, in the order docs/faults.md decides them.
enum class Outcome : std::uint8_t { masked, recovered, safe_stop, sdc_safe, unsafe, hang, error };
const char* to_string(Outcome outcome);

/// One failover as reported: the module, its spare (empty if none) and the boot's time.
struct FailoverFigure {
  std::string failed;
  std::string spare;
  double boot_s = 0.0; ///< from the spare's power-on to it running; 0 when it never ran
};

/// A module halted on an error (HaltOnError): where, why and when.
struct HaltFigure {
  std::string module;
  std::string process;
  std::string what;
  std::string cause;
  double time_s = 0.0;
};

/// A link trouble a module reported: which link, to which module, what, and when.
struct LinkTroubleFigure {
  std::string module;
  int link = 0;
  std::string peer;
  std::string trouble;
  double time_s = 0.0;
};

struct FaultVerdict {
  Outcome outcome = Outcome::error;
  std::string reason; ///< why an error or a hang; empty otherwise
  /// The fault stopped a module: a hang or power loss struck, or a leak made it halt.
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
};

/// Judges a run that ended (finished, abandoned, cut by its time limit, or faulted).
/// `crosses_obstacle` says whether a finished run's path crosses a ground-truth obstacle.
FaultVerdict judge_fault_run(const GoldenRun& golden, const occam_port::CycleEmulation& run,
                             const overswitch::FailoverSupervisor& supervisor,
                             bool crosses_obstacle);

/// The verdict on a run its fault cannot have changed (an upset the EDAC corrects, one in memory
/// no block holds): the fault-free run's, masked, and seen by the EDAC when it corrected it.
FaultVerdict judge_unchanged_run(const GoldenRun& golden, bool edac_corrected);

nlohmann::ordered_json verdict_json(const FaultVerdict& verdict);

/// A fault as it struck: its spec, time, and for a memory fault the bit it hit, the region and
/// buffer, and what that did (the EDAC's correction, the module sent astray...).
nlohmann::ordered_json injected_json(const overswitch::InjectedFault& fault);

} // namespace marsokhod::apps
