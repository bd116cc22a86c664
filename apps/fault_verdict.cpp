// Judging a fault run: outcome class, detection, recovery, telemetry and wheel commands.

#include "fault_verdict.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace marsokhod::apps {
namespace {

namespace emu = emulator;
using overswitch::ReportedTrouble;

bool same_path(const occam_port::CycleEmulation& a, const occam_port::CycleEmulation& b) {
  return a.result && b.result && a.result->plan.found == b.result->plan.found &&
         a.result->plan.pixels == b.result->plan.pixels;
}

// The golden cycle's uploads must be the last ones the device received, byte for byte.
bool telemetry_delivered(const occam_port::CycleEmulation& golden,
                         const occam_port::CycleEmulation& run) {
  if (!run.finished || run.telemetry.size() < golden.telemetry.size())
    return false;
  return std::equal(golden.telemetry.begin(), golden.telemetry.end(),
                    run.telemetry.end() - static_cast<std::ptrdiff_t>(golden.telemetry.size()));
}

/// The fault stopped its module when it struck: a hang, a power loss, or a memory fault that
/// sent the module astray.
bool stopped_module(const overswitch::InjectedFault& fault) {
  return overswitch::stops_module(fault.fault.kind) ||
         (fault.hit && fault.hit->corrupts_control() && fault.effect.starts_with("module hung"));
}

/// The EDAC saw the fault: it corrected it, or flagged it uncorrectable.
bool edac_saw(const overswitch::InjectedFault& fault) {
  return fault.hit && fault.hit->effect != emu::UpsetEffect::flipped;
}

/// The fault reached what the program computes with or runs on.
bool reached_program(const overswitch::InjectedFault& fault) {
  return fault.hit && (fault.hit->corrupts_data() || fault.hit->corrupts_control());
}

/// When each module stopped working: a hang or power loss when it struck, a leak when the
/// module halted on it.
std::vector<std::pair<std::string, emu::Tick>>
failures(const occam_port::CycleEmulation& run, const overswitch::FailoverSupervisor& supervisor) {
  std::vector<std::pair<std::string, emu::Tick>> failed;
  // A hang or power loss after the cycle ended (its run drains the links) stopped nothing.
  for (const overswitch::InjectedFault& fault : supervisor.injected())
    if (stopped_module(fault) && fault.at <= run.emulated)
      failed.emplace_back(fault.fault.module, fault.at);
  for (const occam_port::ModuleHalt& halt : run.halts)
    failed.emplace_back(halt.node, halt.time);
  return failed;
}

// An upload from a module after it stopped working: a failed module commanding the wheels.
bool failed_module_uploaded(const occam_port::CycleEmulation& run,
                            const overswitch::FailoverSupervisor& supervisor) {
  for (const auto& [module, since] : failures(run, supervisor))
    for (const occam_port::DeviceUpload& upload : run.uploads)
      if (upload.node == module && upload.time >= since)
        return true;
  return false;
}

Outcome classify(const FaultVerdict& v, const occam_port::CycleEmulation& run,
                 const overswitch::FailoverSupervisor& supervisor) {
  if (supervisor.error() || (run.memory_fault && !run.finished))
    return Outcome::error;
  if (run.abandoned)
    return Outcome::safe_stop;
  if (!run.finished)
    return Outcome::hang;
  if (v.unsafe && !v.golden_unsafe)
    return Outcome::unsafe;
  if (!v.path_equals_golden)
    return Outcome::sdc_safe;
  return supervisor.overswitch().failovers().empty() && run.restarts == 0 ? Outcome::masked
                                                                          : Outcome::recovered;
}

std::string reason_of(const occam_port::CycleEmulation& run,
                      const overswitch::FailoverSupervisor& supervisor) {
  if (supervisor.error())
    return *supervisor.error();
  if (run.memory_fault)
    return "memory fault on " + run.memory_fault->node + " in " + run.memory_fault->process;
  if (run.abandoned)
    return *run.abandoned;
  if (!run.finished)
    return "the cycle did not end and no watchdog ran out";
  return {};
}

} // namespace

const char* to_string(Outcome outcome) {
  switch (outcome) {
  case Outcome::masked:
    return "masked";
  case Outcome::recovered:
    return "recovered";
  case Outcome::safe_stop:
    return "safe_stop";
  case Outcome::sdc_safe:
    return "sdc_safe";
  case Outcome::unsafe:
    return "unsafe";
  case Outcome::hang:
    return "hang";
  case Outcome::error:
    return "error";
  }
  return "?";
}

FaultVerdict judge_fault_run(const GoldenRun& golden, const occam_port::CycleEmulation& run,
                             const overswitch::FailoverSupervisor& supervisor,
                             bool crosses_obstacle) {
  FaultVerdict v;
  const auto& failovers = supervisor.overswitch().failovers();
  const auto& injected = supervisor.injected();
  const auto& troubles = supervisor.troubles();
  v.detected = !failovers.empty() || !troubles.empty() ||
               std::any_of(injected.begin(), injected.end(), edac_saw);
  // A link fault is known to have reached the program when a module reported the link.
  v.activated = !failures(run, supervisor).empty() || !troubles.empty() ||
                std::any_of(injected.begin(), injected.end(), reached_program);
  for (const overswitch::Failover& f : failovers) {
    const emu::Tick powered = f.detected;
    v.failovers.push_back({f.failed, f.spare, f.ok ? emu::to_seconds(f.booted - powered) : 0.0});
  }
  // Found by a watchdog, a link's timeout or a checksum, whichever came first.
  std::optional<emu::Tick> found;
  if (!failovers.empty())
    found = failovers.front().detected;
  if (!troubles.empty())
    found = std::min(found.value_or(troubles.front().at), troubles.front().at);
  if (found && !injected.empty())
    v.detection_latency_s = emu::to_seconds(*found - injected.front().at);
  const auto whole = std::find_if(failovers.begin(), failovers.end(),
                                  [](const overswitch::Failover& f) { return f.ok; });
  if (whole != failovers.end())
    v.recovery_s = emu::to_seconds(whole->booted - failovers.front().detected);
  v.restarts = run.restarts;
  for (const ReportedTrouble& t : troubles)
    v.link_troubles.push_back(
        {t.module, t.link, t.peer, occam_port::to_string(t.trouble), emu::to_seconds(t.at)});
  for (const occam_port::ModuleHalt& h : run.halts)
    v.halts.push_back({h.node, h.process, h.what, h.cause, emu::to_seconds(h.time)});
  v.path_equals_golden = run.finished && same_path(golden.run, run);
  v.golden_unsafe = golden.unsafe;
  v.unsafe = run.finished && crosses_obstacle;
  v.telemetry_lost = !telemetry_delivered(golden.run, run);
  v.wheels_commanded_while_failed = failed_module_uploaded(run, supervisor);
  v.emulated_s = emu::to_seconds(run.emulated);
  v.delay_s = emu::to_seconds(run.emulated - golden.run.emulated);
  v.outcome = classify(v, run, supervisor);
  v.reason = reason_of(run, supervisor);
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

nlohmann::ordered_json verdict_json(const FaultVerdict& v) {
  nlohmann::ordered_json j;
  j["outcome"] = to_string(v.outcome);
  if (!v.reason.empty())
    j["reason"] = v.reason;
  j["activated"] = v.activated;
  j["detected"] = v.detected;
  j["detection_latency_s"] = v.detection_latency_s ? nlohmann::ordered_json(*v.detection_latency_s)
                                                   : nlohmann::ordered_json(nullptr);
  j["recovery_s"] =
      v.recovery_s ? nlohmann::ordered_json(*v.recovery_s) : nlohmann::ordered_json(nullptr);
  j["failovers"] = nlohmann::ordered_json::array();
  for (const FailoverFigure& f : v.failovers)
    j["failovers"].push_back({{"failed", f.failed},
                              {"spare", f.spare.empty() ? nlohmann::ordered_json(nullptr)
                                                        : nlohmann::ordered_json(f.spare)},
                              {"boot_s", f.boot_s}});
  if (!v.halts.empty()) {
    j["halts"] = nlohmann::ordered_json::array();
    for (const HaltFigure& h : v.halts)
      j["halts"].push_back({{"module", h.module},
                            {"process", h.process},
                            {"what", h.what},
                            {"cause", h.cause},
                            {"time_s", h.time_s}});
  }
  j["restarts"] = v.restarts;
  if (!v.link_troubles.empty()) {
    j["link_troubles"] = nlohmann::ordered_json::array();
    for (const LinkTroubleFigure& t : v.link_troubles)
      j["link_troubles"].push_back({{"module", t.module},
                                    {"link", t.link},
                                    {"peer", t.peer},
                                    {"trouble", t.trouble},
                                    {"time_s", t.time_s}});
  }
  j["path_equals_golden"] = v.path_equals_golden;
  j["unsafe"] = v.unsafe;
  j["golden_unsafe"] = v.golden_unsafe;
  j["telemetry_lost"] = v.telemetry_lost;
  j["wheels_commanded_while_failed"] = v.wheels_commanded_while_failed;
  j["emulated_s"] = v.emulated_s;
  j["delay_s"] = v.delay_s;
  return j;
}

nlohmann::ordered_json injected_json(const overswitch::InjectedFault& f) {
  nlohmann::ordered_json j;
  j["kind"] = overswitch::to_string(f.fault.kind);
  j["module"] = f.fault.module;
  j["at_s"] = emu::to_seconds(f.at);
  j["spec"] = overswitch::describe(f.fault);
  if (!f.effect.empty())
    j["effect"] = f.effect;
  if (!f.hit)
    return j;
  const overswitch::MemoryHit& hit = *f.hit;
  j["address"] = fmt::format("#{:08X}", hit.address);
  j["bit"] = hit.bit;
  j["check_bit"] = hit.check_bit;
  j["region"] = hit.region();
  j["buffer"] = hit.buffer();
  j["owner"] =
      hit.block ? nlohmann::ordered_json(hit.block->owner) : nlohmann::ordered_json(nullptr);
  j["edac"] = emu::to_string(hit.effect);
  return j;
}

} // namespace marsokhod::apps
