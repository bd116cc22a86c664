// Judging a fault run: outcome class, detection, recovery, telemetry and wheel commands.

#include "marsokhod/eval/faults/fault_verdict.hpp"

#include <algorithm>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;
using nav_program::CycleEmulation;
using overswitch::InjectedFault;

bool same_path(const CycleEmulation& a, const CycleEmulation& b) {
  return a.result && b.result && a.result->plan.found == b.result->plan.found &&
         a.result->plan.pixels == b.result->plan.pixels;
}

// The golden cycle's uploads must be the last ones the device received, byte for byte.
bool telemetry_delivered(const CycleEmulation& golden, const CycleEmulation& run) {
  if (!run.finished || run.telemetry.size() < golden.telemetry.size())
    return false;
  return std::equal(golden.telemetry.begin(), golden.telemetry.end(),
                    run.telemetry.end() - static_cast<std::ptrdiff_t>(golden.telemetry.size()));
}

/// The fault stopped its module when it struck: a hang, a power loss, or a memory fault that
/// sent the module astray.
bool stopped_module(const InjectedFault& fault) {
  return overswitch::stops_module(fault.fault.kind) ||
         (fault.hit && fault.hit->corrupts_control() && fault.effect.starts_with("module hung"));
}

/// The EDAC saw the fault: it corrected it, or flagged it uncorrectable.
bool edac_saw(const InjectedFault& fault) {
  return fault.hit && fault.hit->effect != emu::UpsetEffect::flipped;
}

/// The fault reached what the program computes with or runs on.
bool reached_program(const InjectedFault& fault) {
  return fault.hit && (fault.hit->corrupts_data() || fault.hit->corrupts_control());
}

/// When each module stopped working: a hang or power loss when it struck, a leak when the
/// module halted on it.
std::vector<std::pair<std::string, emu::Tick>> failures(const SupervisedRun& run) {
  std::vector<std::pair<std::string, emu::Tick>> failed;
  // A hang or power loss after the cycle ended (its run drains the links) stopped nothing.
  for (const InjectedFault& fault : run.injected)
    if (stopped_module(fault) && fault.at <= run.cycle->emulated)
      failed.emplace_back(fault.fault.module, fault.at);
  for (const nav_program::ModuleHalt& halt : run.cycle->halts)
    failed.emplace_back(halt.node, halt.time);
  return failed;
}

// An upload from a module after it stopped working: a failed module commanding the wheels.
bool failed_module_uploaded(const SupervisedRun& run) {
  for (const auto& [module, since] : failures(run))
    for (const nav_program::DeviceUpload& upload : run.cycle->uploads)
      if (upload.node == module && upload.time >= since)
        return true;
  return false;
}

// The classes in the order docs/faults.md decides them: the first that holds.
Outcome classify(const FaultVerdict& v, const SupervisedRun& run) {
  const CycleEmulation& cycle = *run.cycle;
  if (run.error || (cycle.memory_fault && !cycle.finished))
    return Outcome::error;
  if (cycle.abandoned)
    return Outcome::safe_stop;
  if (!cycle.finished)
    return Outcome::hang;
  if (v.unsafe && !v.golden_unsafe)
    return Outcome::unsafe;
  if (!v.path_equals_golden)
    return Outcome::sdc_safe;
  return run.failovers.empty() && cycle.restarts == 0 ? Outcome::masked : Outcome::recovered;
}

std::string reason_of(const SupervisedRun& run) {
  const CycleEmulation& cycle = *run.cycle;
  if (run.error)
    return *run.error;
  if (cycle.memory_fault)
    return "memory fault on " + cycle.memory_fault->node + " in " + cycle.memory_fault->process;
  if (cycle.abandoned)
    return *cycle.abandoned;
  if (!cycle.finished)
    return "the cycle did not end and no watchdog ran out";
  return {};
}

// Found by a watchdog, a link's timeout or a checksum, whichever came first.
std::optional<double> detection_latency(const SupervisedRun& run) {
  std::optional<emu::Tick> found;
  if (!run.failovers.empty())
    found = run.failovers.front().detected;
  if (!run.troubles.empty())
    found = std::min(found.value_or(run.troubles.front().at), run.troubles.front().at);
  if (!found || run.injected.empty())
    return std::nullopt;
  return emu::to_seconds(*found - run.injected.front().at);
}

void add_figures(FaultVerdict& v, const SupervisedRun& run) {
  for (const overswitch::Failover& f : run.failovers)
    v.failovers.push_back({f.failed, f.spare, f.ok ? emu::to_seconds(f.booted - f.detected) : 0.0});
  const auto whole = std::find_if(run.failovers.begin(), run.failovers.end(),
                                  [](const overswitch::Failover& f) { return f.ok; });
  if (whole != run.failovers.end())
    v.recovery_s = emu::to_seconds(whole->booted - run.failovers.front().detected);
  for (const overswitch::ReportedTrouble& t : run.troubles)
    v.link_troubles.push_back(
        {t.module, t.link, t.peer, nav_program::to_string(t.trouble), emu::to_seconds(t.at)});
  for (const nav_program::ModuleHalt& h : run.cycle->halts)
    v.halts.push_back({h.node, h.process, h.what, h.cause, emu::to_seconds(h.time)});
}

} // namespace

SupervisedRun supervised_run(const CycleEmulation& cycle,
                             const overswitch::FailoverSupervisor& supervisor) {
  return {&cycle, supervisor.overswitch().failovers(), supervisor.injected(), supervisor.troubles(),
          supervisor.error()};
}

FaultVerdict judge_fault_run(const GoldenRun& golden, const SupervisedRun& run,
                             bool crosses_obstacle) {
  const CycleEmulation& cycle = *run.cycle;
  FaultVerdict v;
  v.detected = !run.failovers.empty() || !run.troubles.empty() ||
               std::any_of(run.injected.begin(), run.injected.end(), edac_saw);
  // A link fault is known to have reached the program when a module reported the link.
  v.activated = !failures(run).empty() || !run.troubles.empty() ||
                std::any_of(run.injected.begin(), run.injected.end(), reached_program);
  v.detection_latency_s = detection_latency(run);
  add_figures(v, run);
  v.restarts = cycle.restarts;
  v.path_equals_golden = cycle.finished && same_path(golden.run, cycle);
  v.golden_unsafe = golden.unsafe;
  v.unsafe = cycle.finished && crosses_obstacle;
  v.telemetry_lost = !telemetry_delivered(golden.run, cycle);
  v.wheels_commanded_while_failed = failed_module_uploaded(run);
  v.emulated_s = emu::to_seconds(cycle.emulated);
  v.delay_s = emu::to_seconds(cycle.emulated - golden.run.emulated);
  v.outcome = classify(v, run);
  v.reason = reason_of(run);
  return v;
}

FaultVerdict judge_unchanged_run(const GoldenRun& golden, bool edac_corrected) {
  FaultVerdict v;
  v.outcome = Outcome::masked;
  v.detected = edac_corrected;
  v.path_equals_golden = true;
  v.golden_unsafe = golden.unsafe;
  v.unsafe = golden.unsafe;
  v.emulated_s = emu::to_seconds(golden.run.emulated);
  return v;
}

} // namespace marsokhod::eval
